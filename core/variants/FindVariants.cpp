#include "variants/FindVariants.h"

#include <utility>

namespace matevo {

Result<FoundVariants> findVariants(const MaterialInstance& target, const VariantRequest& request,
                                   const VariantSearchSettings& settings,
                                   RenderGenomes fitnessRender, const RenderGenomes& outputRender,
                                   const VariantSearchHooks& hooks,
                                   const DeliveryFormat* delivery) {
    auto search = VariantSearch::start(target, request, settings, std::move(fitnessRender));
    if (!search) return search.error();
    if (auto ran = (*search)->run(hooks); !ran) return ran.error();
    auto set = chooseVariantSet((*search)->archive(), request, target.genome, outputRender);
    if (!set) return set.error();
    // A stopped search is delivered unchecked (marked partial by the caller): the check's fits
    // would keep the user waiting after they asked to stop.
    if (!delivery || (hooks.stop && hooks.stop()))
        return FoundVariants{std::move(set).value(), (*search)->progress(), {}};
    auto delivered = checkDelivery((*search)->archive(), std::move(set).value(), request,
                                   target.genome, outputRender, *delivery);
    if (!delivered) return delivered.error();
    return FoundVariants{std::move(delivered->set), (*search)->progress(),
                         std::move(delivered->delivered)};
}

}  // namespace matevo
