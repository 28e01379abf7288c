#include "variants/VariantFiles.h"

#include <algorithm>
#include <cstdio>

#include "color/Colormap.h"
#include "color/ImageDifference.h"
#include "documents/CarriedTextures.h"
#include "documents/GenomeJson.h"
#include "files/AtomicFile.h"
#include "fitness/RenderGenomesWith.h"
#include "image/Canvas.h"
#include "image/ImageFile.h"
#include "variants/DeliveredFiles.h"

namespace matevo {
namespace {

constexpr int kSheetColumns = 5;
constexpr int kSheetGap = 8;
constexpr double kLabelSize = 14;  // pixels per em
constexpr int kLabelLineHeight = 18;
constexpr Srgb8 kSheetBackground{40, 40, 44};
constexpr Srgb8 kLabelColour{230, 230, 230};

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

Status createFolder(const std::filesystem::path& folder) {
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error)
        return badInput("cannot create folder '" + folder.string() + "' (" + error.message() + ")");
    return Ok{};
}

// `tile` composited with its alpha over the sheet at (x, y).
void placeTile(Image& sheet, const Image& tile, int x, int y) {
    for (int row = 0; row < tile.height; ++row)
        for (int column = 0; column < tile.width; ++column) {
            const float* source = tile.pixel(column, row);
            float* target = sheet.pixel(x + column, y + row);
            const float alpha = std::clamp(source[3], 0.0f, 1.0f);
            for (int c = 0; c < 3; ++c) target[c] = alpha * source[c] + (1 - alpha) * target[c];
        }
}

// "paper", "paper and studio", "paper, ambient and studio".
std::string listOfLightings(const std::vector<std::string>& lightings) {
    std::string text;
    for (std::size_t i = 0; i < lightings.size(); ++i)
        text += (i == 0 ? "" : i + 1 == lightings.size() ? " and " : ", ") + lightings[i];
    return text;
}

}  // namespace

RenderGenomes asStoredInPng(RenderGenomes render) {
    return [render =
                std::move(render)](std::span<const Genome> genomes) -> Result<std::vector<Image>> {
        auto images = render(genomes);
        if (!images) return images.error();
        for (Image& image : *images) image = quantizeAsPng(image);
        return images;
    };
}

LightingRenders renderUnderEachLighting(const std::vector<LitScene>& lit,
                                        const MaterialFamily& family,
                                        const std::array<double, 3>& kappa, int size) {
    std::vector<RenderGenomes> perLighting;
    for (const LitScene& lighting : lit)
        perLighting.push_back(asStoredInPng(
            renderGenomesWith(lighting.renderer, family, kappa, lighting.scene, size)));
    return LightingRenders(std::move(perLighting));
}

std::string variantStem(std::size_t index, std::size_t count) {
    int digits = 3;
    for (std::size_t last = count > 0 ? count - 1 : 0; last >= 1000; last /= 10) ++digits;
    char name[48];
    std::snprintf(name, sizeof name, "variant_%0*zu", digits, index);
    return name;
}

nlohmann::ordered_json variantEntry(const Preset& preset, const VariantSet& set, std::size_t member,
                                    std::size_t index, std::size_t count,
                                    const std::vector<double>& nearest) {
    const Variant& variant = set.variants[member];
    const MaterialInstance material = materialOf(variant.genome, preset.family, preset.baseKappa);
    const std::string stem = "variants/" + variantStem(index, count);
    nlohmann::ordered_json entry = {{"index", index},
                                    {"file", stem + ".json"},
                                    {"image", stem + ".png"},
                                    {"heatmap", stem + "_heatmap.png"},
                                    {"de00_to_target", variant.deltaEToTarget},
                                    {"de00_to_nearest_sibling", nearest[member]}};
    if (!set.lightings.empty()) {
        nlohmann::ordered_json byLighting = nlohmann::ordered_json::object();
        for (std::size_t lighting = 0; lighting < set.lightings.size(); ++lighting)
            byLighting[set.lightings[lighting]] = {
                {"to_target", variant.deltaEUnder(lighting)},
                {"to_nearest_sibling", set.nearestSibling(lighting)[member]}};
        entry["de00_by_lighting"] = std::move(byLighting);
    }
    entry["kept"] = variant.kept;
    entry["genome"] = genomeToJson(material.genome);
    if (variant.genome.carriesKappa()) entry["base_kappa"] = material.baseKappa;
    return entry;
}

nlohmann::ordered_json requestJson(const VariantRun& run) {
    const VariantRequest& request = run.request;
    nlohmann::ordered_json json = {{"count", request.count},
                                   {"band", {request.band.low, request.band.high}},
                                   {"min_apart", request.minApart},
                                   {"seed", request.seed},
                                   {"hue_variety", request.kappaGenes == KappaGenes::On},
                                   {"size", run.size},
                                   {"fitness_size", run.fitnessSize}};
    if (!request.lightings.empty()) json["lightings"] = request.lightings;
    return json;
}

nlohmann::ordered_json pairwiseByLighting(const VariantSet& set) {
    nlohmann::ordered_json matrices = nlohmann::ordered_json::object();
    for (std::size_t lighting = 0; lighting < set.lightings.size(); ++lighting)
        matrices[set.lightings[lighting]] = set.pairwiseUnder(lighting);
    return matrices;
}

nlohmann::ordered_json variantReport(const Preset& preset, const VariantRun& run,
                                     const VariantSet& set, const DeliveredSet* delivered) {
    const std::vector<double> nearest = set.nearestSibling();
    nlohmann::ordered_json variants = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < set.variants.size(); ++i) {
        variants.push_back(variantEntry(preset, set, i, i, 0, nearest));
        if (delivered) variants.back()["delivered"] = deliveredEntry(*delivered, i, i);
    }
    const VariantRequest& request = run.request;
    const bool met = fulfils(set, request);
    nlohmann::ordered_json report = {{"preset", preset.name},
                                     {"family", describe(preset.family)},
                                     {"target", genomeToJson(preset.target)},
                                     {"request", requestJson(run)}};
    if (!run.madeBy.is_null()) report["made_by"] = run.madeBy;
    report.update(nlohmann::ordered_json{
        {"met", met},
        {"summary", variantSummary(run, set) +
                        (delivered ? deliverySummary(*delivered, request) : std::string())},
        {"variants", std::move(variants)},
        {"pairwise_de00", set.pairwise}});
    if (!set.lightings.empty()) report["pairwise_de00_by_lighting"] = pairwiseByLighting(set);
    report["smallest_pairwise_de00"] = set.smallestPairwise;
    if (delivered) report["delivery"] = deliveryJson(*delivered);
    report.update(nlohmann::ordered_json{{"evaluations", run.evaluations},
                                         {"archived", run.archived},
                                         {"output_renders", set.outputRenders},
                                         {"wall_time_s", run.wallSeconds},
                                         {"seed", request.seed}});
    return report;
}

std::string variantSummary(const VariantRun& run, const VariantSet& set) {
    const VariantRequest& request = run.request;
    // Kept materials join a set as they are: the line says what holds, never more.
    const auto inBand = std::count_if(
        set.variants.begin(), set.variants.end(),
        [&](const Variant& variant) { return request.band.contains(variant.deltaEToTarget); });
    std::string text =
        std::to_string(set.variants.size()) + " of " + std::to_string(request.count) + " variants";
    if (std::size_t(inBand) == set.variants.size())
        text += " in band " + describe(request.band);
    else
        text += ", " + std::to_string(inBand) + " in band " + describe(request.band);
    if (!request.lightings.empty()) text += " under " + listOfLightings(request.lightings);
    const bool apart = set.variants.size() < 2 || set.smallestPairwise >= request.minApart;
    if (apart) text += ", at least " + format("%g", request.minApart) + " apart";
    if (set.variants.size() > 1)
        text += apart ? " (smallest pairwise " + format("%.2f", set.smallestPairwise) + ")"
                      : ", smallest pairwise " + format("%.2f", set.smallestPairwise) +
                            " (asked at least " + format("%g", request.minApart) + ")";
    text += ", " + std::to_string(run.evaluations) + " evaluations";
    if (set.variants.empty())
        text += "; the render nearest the band was " + format("%.2f", run.closestDeltaE) +
                " from the target";
    return text;
}

Image contactSheet(const VariantSet& set, const Font& font, std::size_t firstIndex,
                   std::size_t count) {
    const int tile = std::max(set.target.width, 1);
    const int labelHeight = 2 * kLabelLineHeight + kSheetGap / 2;
    const int cells = int(set.variants.size()) + 1;
    const int columns = std::min(cells, kSheetColumns);
    const int rows = (cells + columns - 1) / columns;
    Canvas canvas(columns * (tile + kSheetGap) + kSheetGap,
                  rows * (tile + labelHeight + kSheetGap) + kSheetGap, kSheetBackground);
    const std::vector<double> nearest = set.nearestSibling();
    auto origin = [&](int cell) {
        return std::pair{kSheetGap + (cell % columns) * (tile + kSheetGap),
                         kSheetGap + (cell / columns) * (tile + labelHeight + kSheetGap)};
    };
    // Baselines of the two label lines under a tile whose top is at y.
    auto firstBaseline = [&](int y) { return double(y + tile + kLabelLineHeight); };
    auto [targetX, targetY] = origin(0);
    canvas.drawText(font, targetX, firstBaseline(targetY), "target", kLabelSize, kLabelColour);
    for (std::size_t i = 0; i < set.variants.size(); ++i) {
        auto [x, y] = origin(int(i) + 1);
        canvas.drawText(font, x, firstBaseline(y),
                        variantStem(firstIndex + i, count).substr(8) + "  ΔE00 " +
                            format("%.2f", set.variants[i].deltaEToTarget),
                        kLabelSize, kLabelColour);
        canvas.drawText(font, x, firstBaseline(y) + kLabelLineHeight,
                        "nearest " + format("%.2f", nearest[i]), kLabelSize, kLabelColour);
    }
    Image sheet = std::move(canvas).release();
    placeTile(sheet, set.target, targetX, targetY);
    for (std::size_t i = 0; i < set.variants.size(); ++i) {
        auto [x, y] = origin(int(i) + 1);
        placeTile(sheet, set.variants[i].image, x, y);
    }
    return sheet;
}

std::filesystem::path targetMaterialFile(const std::filesystem::path& dir) {
    return dir / "target.json";
}

MaterialFile variantMaterial(const MaterialFile& target, const Variant& variant, std::size_t index,
                             std::size_t count) {
    MaterialFile material = target;
    material.name =
        (target.name.empty() ? std::string() : target.name + " ") + variantStem(index, count);
    // The variant's own kappa when it carries kappa genes (hue variety), else the target's.
    material.material =
        materialOf(variant.genome, target.material.family, target.material.baseKappa);
    return material;
}

Status writeVariantMembers(const std::filesystem::path& dir, const MaterialFile& target,
                           const VariantSet& set, std::size_t firstIndex, std::size_t count,
                           ImageMetric heatmapMetric) {
    const std::filesystem::path folder = dir / "variants";
    if (auto created = createFolder(folder); !created) return created;
    // The set carries its textures, so that it renders wherever it is moved
    // (documents/CarriedTextures.h).
    auto carried = carryTextures(target, dir);
    if (!carried) return carried.error();
    if (auto written = saveMaterial(*carried, targetMaterialFile(dir)); !written) return written;
    for (std::size_t i = 0; i < set.variants.size(); ++i) {
        const Variant& variant = set.variants[i];
        const std::size_t index = firstIndex + i;
        const std::string stem = variantStem(index, count);
        if (auto written = saveMaterial(variantMaterial(*carried, variant, index, count),
                                        folder / (stem + ".json"));
            !written)
            return written;
        if (auto written = writeImage(variant.image, folder / (stem + ".png")); !written)
            return written;
        auto heatmap = errorHeatmap(set.target, variant.image, heatmapMetric);
        if (!heatmap) return heatmap.error();
        if (auto written = writeImage(*heatmap, folder / (stem + "_heatmap.png")); !written)
            return written;
    }
    return Ok{};
}

Status writeVariantFiles(const std::filesystem::path& dir, const MaterialFile& target,
                         const VariantSet& set, const nlohmann::ordered_json& report,
                         const Font& font, ImageMetric heatmapMetric) {
    if (auto written = writeVariantMembers(dir, target, set, 0, 0, heatmapMetric); !written)
        return written;
    if (auto written = writeImage(set.target, dir / "target.png"); !written) return written;
    if (auto written = writeImage(contactSheet(set, font), dir / "contact_sheet.png"); !written)
        return written;
    return writeFileAtomically(dir / "report.json", report.dump(2) + "\n");
}

Status saveVariantFolder(OutputFolder& output, const MaterialFile& target, const VariantSet& set,
                         const nlohmann::ordered_json& report, const Font& font,
                         ImageMetric heatmapMetric) {
    if (auto written =
            writeVariantFiles(output.staging(), target, set, report, font, heatmapMetric);
        !written)
        return output.userFacing(written.error());
    return output.commit();
}

}  // namespace matevo
