#include "variants/FindVariants.h"

#include <utility>

namespace matevo {

Result<FoundVariants> findVariants(const MaterialInstance& target, const VariantRequest& request,
                                   const VariantSearchSettings& settings,
                                   const LightingRenders& fitnessRender,
                                   const LightingRenders& outputRender, const CancelToken& cancel,
                                   const VariantSearchObserver& onGeneration,
                                   const DeliveryFormat* delivery) {
    // The delivered looks are measured under one lighting, as the glTF reference renders them.
    if (delivery && outputRender.count() > 1)
        return badInput("a delivery check takes one lighting, not " +
                        std::to_string(outputRender.count()));
    auto search = VariantSearch::start(target, request, settings, fitnessRender);
    if (!search) return search.error();
    if (auto ran = (*search)->run(cancel, onGeneration); !ran) return ran.error();
    auto set = chooseVariantSet((*search)->archive(), request, target.genome, outputRender);
    if (!set) return set.error();
    // A stopped search is delivered unchecked (marked partial by the caller): the check's fits
    // would keep the user waiting after they asked to stop.
    if (!delivery || cancel.cancelled())
        return FoundVariants{std::move(set).value(), (*search)->progress(), {}};
    auto delivered = checkDelivery((*search)->archive(), std::move(set).value(), request,
                                   target.genome, outputRender.perLighting.front(), *delivery);
    if (!delivered) return delivered.error();
    return FoundVariants{std::move(delivered->set), (*search)->progress(),
                         std::move(delivered->delivered)};
}

}  // namespace matevo
