#include "variants/DeliveredFiles.h"

#include <algorithm>
#include <cstdio>

#include "image/ImageFile.h"
#include "variants/VariantFiles.h"

namespace matevo {
namespace {

std::string fixed2(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", value);
    return text;
}

}  // namespace

std::filesystem::path deliveredFolder(const std::filesystem::path& dir) {
    return dir / "delivered";
}

nlohmann::ordered_json deliveredFigures(const DeliveredSet& delivered, std::size_t member) {
    const DeliveredVariant& variant = delivered.variants[member];
    return {{"de00_to_target", variant.deltaEToTarget},
            {"de00_to_nearest_sibling", nearestSiblings(delivered.pairwise)[member]},
            {"de00_to_matevo", variant.deltaEToMatevo},
            {"within_goal", delivered.withinGoal(member)},
            {"refitted", variant.attempt > 0}};
}

nlohmann::ordered_json deliveredEntry(const DeliveredSet& delivered, std::size_t member,
                                      std::size_t index) {
    nlohmann::ordered_json entry{{"image", "delivered/" + variantStem(index) + ".png"}};
    entry.update(deliveredFigures(delivered, member));
    return entry;
}

nlohmann::ordered_json deliveryFigures(const DeliveredSet& delivered) {
    return {{"goal_mean_de00", delivered.goalDeltaE},
            {"target_de00_to_matevo", delivered.targetToMatevo},
            {"pairwise_de00", delivered.pairwise},
            {"smallest_pairwise_de00", delivered.smallestPairwise},
            {"conversions", delivered.conversions},
            {"refitted", delivered.refitted},
            {"replaced", delivered.replaced}};
}

nlohmann::ordered_json deliveryJson(const DeliveredSet& delivered) {
    nlohmann::ordered_json json{{"format", delivered.format}, {"folder", "delivered"}};
    json.update(deliveryFigures(delivered));
    return json;
}

std::string deliverySummary(const DeliveredSet& delivered, const VariantRequest& request) {
    std::size_t inBand = 0, withinGoal = 0;
    for (std::size_t i = 0; i < delivered.variants.size(); ++i) {
        inBand += request.band.contains(delivered.variants[i].deltaEToTarget) ? 1 : 0;
        withinGoal += delivered.withinGoal(i) ? 1 : 0;
    }
    std::string text =
        "; delivered as " + delivered.format + ": " + std::to_string(inBand) + " in band";
    if (delivered.variants.size() > 1)
        text += ", smallest pairwise " + fixed2(delivered.smallestPairwise);
    return text + ", " + std::to_string(withinGoal) + " within the export goal (mean dE00 " +
           fixed2(delivered.goalDeltaE) + " to matevo's render)";
}

Status writeDeliveredLooks(const std::filesystem::path& dir, const DeliveredSet& delivered) {
    const std::filesystem::path folder = deliveredFolder(dir);
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error)
        return badInput("cannot create folder '" + folder.string() + "' (" + error.message() + ")");
    if (auto written = writeImage(delivered.target, folder / "target.png"); !written)
        return written;
    for (std::size_t i = 0; i < delivered.variants.size(); ++i)
        if (auto written =
                writeImage(delivered.variants[i].image, folder / (variantStem(i) + ".png"));
            !written)
            return written;
    return Ok{};
}

}  // namespace matevo
