#pragma once
// A whole variant request, the one way every caller runs it (`matevo variants`, the editor's
// Variants mode, the bench): the quality-diversity search (VariantSearch::run) at the fitness
// resolution until it is finished or the caller stops it (hooks), then the set
// chosen from its archive and checked at the output resolution (chooseVariantSet), then, when a
// delivery format is asked for, checked in that format too (checkDelivery). A stopped search
// still gives the set its archive holds, so a caller can deliver it, marked partial.
#include <optional>

#include "common/Result.h"
#include "evolve/RenderGenomes.h"
#include "material/MaterialInstance.h"
#include "variants/DeliveryCheck.h"
#include "variants/VariantSearch.h"
#include "variants/VariantSet.h"

namespace matevo {

struct FoundVariants {
    VariantSet set;
    VariantSearchProgress progress;  // the search's at its end
    std::optional<DeliveredSet> delivered;  // with a delivery format: the set's delivered looks
};

// `fitnessRender` draws at the fitness resolution, `outputRender` at the output resolution (as
// for VariantSearch::start and chooseVariantSet); `delivery`, when given, the format the set is
// delivered in (DeliveryCheck.h). An Error when rendering failed.
Result<FoundVariants> findVariants(const MaterialInstance& target, const VariantRequest& request,
                                   const VariantSearchSettings& settings,
                                   RenderGenomes fitnessRender, const RenderGenomes& outputRender,
                                   const VariantSearchHooks& hooks = {},
                                   const DeliveryFormat* delivery = nullptr);

}  // namespace matevo
