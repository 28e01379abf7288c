#include "VariantsDisplay.h"

#include "ImageBridge.h"
#include "Rgba8Image.h"
#include "variants/VariantFiles.h"

namespace matevo::editor {
namespace {

// Texture slots after those of the evolution grid and of "Compare metrics".
constexpr std::size_t kTargetSlot = 3000;
constexpr std::size_t kFirstVariantSlot = 3001;

}  // namespace

void showVariants(const VariantsResult& result, ImageBridge& bridge, ui::VariantsView& view) {
    view.variants.clear();
    view.pairwise.clear();
    if (!result.error.empty()) {
        view.summary = "Failed: " + result.error;
        view.met = false;
        return;
    }
    const VariantSet& set = result.set;
    view.summary = variantSummary(result.run, set);
    view.met = fulfils(set, result.run.request);
    view.target = bridge.setImage(kTargetSlot, toDisplayImage(set.target));
    const std::vector<double> nearest = set.nearestSibling();
    for (std::size_t i = 0; i < set.variants.size(); ++i) {
        const Variant& variant = set.variants[i];
        view.variants.push_back({variant.genome,
                                 bridge.setImage(kFirstVariantSlot + i,
                                                 toDisplayImage(variant.image)),
                                 variant.deltaEToTarget, nearest[i], variant.kept});
    }
    view.pairwise = set.pairwise;
}

}  // namespace matevo::editor
