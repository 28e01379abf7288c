#include "VariantsDisplay.h"

#include "variants/VariantFiles.h"

namespace matevo::editor {

Result<std::vector<std::shared_ptr<ShownImage>>> showVariants(const VariantsResult& result,
                                                              ImageBridge& bridge,
                                                              ui::VariantsView& view) {
    view.variants.clear();
    view.pairwise.clear();
    view.target = nullptr;
    if (!result.error.empty()) {
        view.summary = "Failed: " + result.error;
        view.met = false;
        return std::vector<std::shared_ptr<ShownImage>>{};
    }
    const VariantSet& set = result.set;
    std::vector<Image> images{set.target};  // the target first, then the variants
    for (const Variant& variant : set.variants) images.push_back(variant.image);
    auto shown = bridge.upload(images);
    if (!shown) return shown.error();
    view.summary = variantSummary(result.run, set);
    view.met = fulfils(set, result.run.request);
    view.target = (*shown)[0]->render();
    view.imageSize = set.target.width;
    if (view.selected >= int(set.variants.size())) view.selected = -1;
    const std::vector<double> nearest = set.nearestSibling();
    for (std::size_t i = 0; i < set.variants.size(); ++i) {
        const Variant& variant = set.variants[i];
        view.variants.push_back({variant.genome, (*shown)[i + 1]->render(),
                                 variant.deltaEToTarget, nearest[i], variant.kept});
    }
    view.pairwise = set.pairwise;
    return shown;
}

}  // namespace matevo::editor
