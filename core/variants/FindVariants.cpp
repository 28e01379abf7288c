#include "variants/FindVariants.h"

#include <utility>

namespace matevo {

Result<FoundVariants> findVariants(const MaterialInstance& target, const VariantRequest& request,
                                   const VariantSearchSettings& settings,
                                   const LightingRenders& fitnessRender,
                                   const LightingRenders& outputRender,
                                   const CancelToken& cancel,
                                   const VariantSearchObserver& onGeneration) {
    auto search = VariantSearch::start(target, request, settings, fitnessRender);
    if (!search) return search.error();
    if (auto ran = (*search)->run(cancel, onGeneration); !ran) return ran.error();
    auto set = chooseVariantSet((*search)->archive(), request, target.genome, outputRender);
    if (!set) return set.error();
    return FoundVariants{std::move(set).value(), (*search)->progress()};
}

}  // namespace matevo
