#include "VariantsDisplay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "variants/VariantFiles.h"

namespace matevo::editor {
namespace {

// The smallest ΔE00 from delivered look `member` to another; 0 when it is alone.
double nearestDelivered(const DeliveredSet& delivered, std::size_t member) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t other = 0; other < delivered.pairwise[member].size(); ++other)
        if (other != member) nearest = std::min(nearest, delivered.pairwise[member][other]);
    return std::isfinite(nearest) ? nearest : 0.0;
}

}  // namespace

std::string deliveredSummary(const DeliveredSet& delivered, const VariantRequest& request) {
    const std::size_t count = delivered.variants.size();
    std::size_t holding = 0, withinGoal = 0;
    for (std::size_t i = 0; i < count; ++i) {
        holding += deliveredHolds(delivered, i, request) ? 1 : 0;
        withinGoal += delivered.withinGoal(i) ? 1 : 0;
    }
    const std::string format = delivered.format == "gltf" ? "glTF" : delivered.format;
    char text[320];
    int length = std::snprintf(text, sizeof text,
                               "as delivered in %s: %zu/%zu in band %g–%g and ≥ %g apart; fitted "
                               "ΔE00 ≤ %g for %zu/%zu",
                               format.c_str(), holding, count, request.band.low, request.band.high,
                               request.minApart, delivered.goalDeltaE, withinGoal, count);
    if (std::size_t(length) < sizeof text && (delivered.refitted > 0 || delivered.replaced > 0))
        std::snprintf(text + length, sizeof text - std::size_t(length),
                      " (%zu refitted, %zu replaced from the archive)", delivered.refitted,
                      delivered.replaced);
    return text;
}

Result<std::vector<std::shared_ptr<ShownImage>>> showVariants(const VariantsResult& result,
                                                              ImageBridge& bridge,
                                                              ui::VariantsView& view) {
    view.variants.clear();
    view.pairwise.clear();
    view.target = nullptr;
    if (!result.error.empty()) {
        view.summary = "Failed: " + result.error;
        view.met = false;
        view.deliveredSummary.clear();
        return std::vector<std::shared_ptr<ShownImage>>{};
    }
    const VariantSet& set = result.set;
    std::vector<Image> images{set.target};  // the target first, then the variants
    for (const Variant& variant : set.variants) images.push_back(variant.image);
    auto shown = bridge.upload(images);
    if (!shown) return shown.error();
    view.summary = variantSummary(result.run, set);
    const DeliveredSet* delivered = result.delivered ? &*result.delivered : nullptr;
    view.deliveredSummary = delivered ? deliveredSummary(*delivered, result.run.request) : "";
    view.deliveredMet = delivered != nullptr;
    view.met = fulfils(set, result.run.request);
    view.target = (*shown)[0]->render();
    view.imageSize = set.target.width;
    if (view.selected >= int(set.variants.size())) view.selected = -1;
    const std::vector<double> nearest = set.nearestSibling();
    for (std::size_t i = 0; i < set.variants.size(); ++i) {
        const Variant& variant = set.variants[i];
        view.variants.push_back({variant.genome,
                                 (*shown)[i + 1]->render(),
                                 variant.deltaEToTarget,
                                 nearest[i],
                                 variant.kept,
                                 {}});
        if (!delivered) continue;
        const bool holds = deliveredHolds(*delivered, i, result.run.request);
        view.deliveredMet = view.deliveredMet && holds;
        view.variants.back().delivered = ui::VariantTileView::Delivered{
            delivered->variants[i].deltaEToTarget, nearestDelivered(*delivered, i),
            delivered->variants[i].deltaEToMatevo, holds};
    }
    view.pairwise = set.pairwise;
    return shown;
}

}  // namespace matevo::editor
