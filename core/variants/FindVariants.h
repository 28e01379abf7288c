#pragma once
// A whole variant request, the one way every caller runs it (`matevo variants`, the editor's
// Variants mode, the bench): the quality-diversity search (VariantSearch::run) at the fitness
// resolution until it is finished or the caller cancels it, then the set chosen from its
// archive and checked at the output resolution (chooseVariantSet), then, when a delivery format
// is asked for, checked in that format too (checkDelivery). A search stopped by `cancel` still
// gives the set its archive holds, so a caller can deliver it, marked partial.
#include <optional>

#include "common/Result.h"
#include "material/MaterialInstance.h"
#include "variants/DeliveryCheck.h"
#include "variants/LightingMeasure.h"
#include "variants/VariantSearch.h"
#include "variants/VariantSet.h"

namespace matevo {

struct FoundVariants {
    VariantSet set;
    VariantSearchProgress progress;         // the search's at its end
    std::optional<DeliveredSet> delivered;  // with a delivery format: the set's delivered looks
};

// `fitnessRender` draws at the fitness resolution, `outputRender` at the output resolution, each
// once per lighting of the request (as for VariantSearch::start and chooseVariantSet);
// `delivery`, when given, the format the set is delivered in (DeliveryCheck.h), checked under
// the one lighting it allows. An Error when rendering failed.
Result<FoundVariants> findVariants(const MaterialInstance& target, const VariantRequest& request,
                                   const VariantSearchSettings& settings,
                                   const LightingRenders& fitnessRender,
                                   const LightingRenders& outputRender,
                                   const CancelToken& cancel = {},
                                   const VariantSearchObserver& onGeneration = {},
                                   const DeliveryFormat* delivery = nullptr);

}  // namespace matevo
