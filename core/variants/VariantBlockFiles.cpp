#include "variants/VariantBlockFiles.h"
#include "files/JsonReader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "documents/GenomeJson.h"
#include "image/ImageFile.h"

namespace matevo {

namespace {

std::size_t indexOf(const nlohmann::ordered_json& entry) {
    return jsonInteger<std::size_t>(entry.at("index"));
}

void sortByIndex(std::vector<nlohmann::ordered_json>& entries) {
    std::sort(entries.begin(), entries.end(),
              [](const auto& a, const auto& b) { return indexOf(a) < indexOf(b); });
}

}  // namespace

std::vector<int> missingBlocks(const BlockReport& parts, const std::optional<Shard>& shard) {
    const nlohmann::ordered_json& request = parts.header.at("request");
    const VariantBlocks plan{jsonInteger<int>(request.at("count")),
                             jsonInteger<int>(request.at("block"))};
    std::vector<int> missing;
    for (const int block : blocksOfShard(plan, shard.value_or(Shard{})))
        if (std::none_of(parts.blocks.begin(), parts.blocks.end(),
                         [block](const auto& entry) { return int(indexOf(entry)) == block; }))
            missing.push_back(block);
    return missing;
}

std::optional<std::string> madeByConflict(const nlohmann::ordered_json& a,
                                          const nlohmann::ordered_json& b) {
    auto field = [](const nlohmann::ordered_json& madeBy, const char* key) {
        return madeBy.is_object() ? madeBy.value(key, nlohmann::ordered_json())
                                  : nlohmann::ordered_json();
    };
    for (const char* key : {"matevo", "backend"})
        if (field(a, key) != field(b, key)) return std::string("made_by.") + key;
    return std::nullopt;
}

BlockReport blockReportHeader(const Preset& preset, const VariantRun& whole,
                              const VariantBlocks& plan) {
    nlohmann::ordered_json request = requestJson(whole);
    request["block"] = plan.blockSize;
    return {{{"preset", preset.name},
             {"family", describe(preset.family)},
             {"target", genomeToJson(preset.target)},
             {"request", std::move(request)}},
            {},
            {}};
}

void addBlock(BlockReport& report, const Preset& preset, const VariantRun& run,
              const VariantSet& set, const VariantBlocks& plan, int block) {
    const std::size_t first = std::size_t(plan.firstIndex(block));
    report.blocks.push_back({{"index", block},
                             {"seed", run.request.seed},
                             {"first_variant", first},
                             {"count", run.request.count},
                             {"found", set.variants.size()},
                             {"met", fulfils(set, run.request)},
                             {"summary", variantSummary(run, set)},
                             {"evaluations", run.evaluations},
                             {"archived", run.archived},
                             {"output_renders", set.outputRenders},
                             {"pairwise_de00", set.pairwise}});
    nlohmann::ordered_json& added = report.blocks.back();
    if (!set.lightings.empty()) added["pairwise_de00_by_lighting"] = pairwiseByLighting(set);
    added["smallest_pairwise_de00"] = set.smallestPairwise;
    added["contact_sheet"] = blockContactSheet(block);
    const std::vector<double> nearest = set.nearestSibling();
    for (std::size_t i = 0; i < set.variants.size(); ++i) {
        nlohmann::ordered_json entry =
            variantEntry(preset, set, i, first + i, std::size_t(plan.count), nearest);
        entry["block"] = block;
        report.variants.push_back(std::move(entry));
    }
}

nlohmann::ordered_json assembleBlockReport(BlockReport parts, const std::optional<Shard>& shard) {
    sortByIndex(parts.blocks);
    sortByIndex(parts.variants);
    // A material found by two blocks (the genome, and its own kappa with hue variety): the
    // later index is the copy.
    nlohmann::ordered_json duplicates = nlohmann::ordered_json::array();
    std::map<std::string, std::size_t> firstWithGenome;
    for (const auto& variant : parts.variants) {
        const std::string identity = variant.at("genome").dump() +
                                     variant.value("base_kappa", nlohmann::ordered_json()).dump();
        const auto [found, inserted] = firstWithGenome.emplace(identity, indexOf(variant));
        if (!inserted) duplicates.push_back({found->second, indexOf(variant)});
    }
    long long asked = 0;  // a sum over blocks a user may have edited: no int overflow
    bool everyBlockMet = true;
    std::size_t evaluations = 0, archived = 0, outputRenders = 0;
    double smallest = std::numeric_limits<double>::infinity();
    for (const auto& block : parts.blocks) {
        asked += jsonInteger<int>(block.at("count"));
        everyBlockMet = everyBlockMet && block.at("met").get<bool>();
        evaluations += jsonInteger<std::size_t>(block.at("evaluations"));
        archived += jsonInteger<std::size_t>(block.at("archived"));
        outputRenders += jsonInteger<std::size_t>(block.at("output_renders"));
        if (jsonInteger<std::size_t>(block.at("found")) > 1)
            smallest = std::min(smallest, block.at("smallest_pairwise_de00").get<double>());
    }
    if (!std::isfinite(smallest)) smallest = 0;
    const nlohmann::ordered_json& request = parts.header.at("request");
    const std::vector<int> missing = missingBlocks(parts, shard);
    char text[512];
    std::snprintf(text, sizeof text,
                  "%zu of %lld variants in %zu block(s) of up to %d, band %g-%g, at least %g apart "
                  "within each block (smallest %.2f), %zu evaluations",
                  parts.variants.size(), asked, parts.blocks.size(),
                  jsonInteger<int>(request.at("block")), request.at("band")[0].get<double>(),
                  request.at("band")[1].get<double>(), request.at("min_apart").get<double>(),
                  smallest, evaluations);
    std::string summary = text;
    if (!duplicates.empty())
        summary += "; " + std::to_string(duplicates.size()) + " genome(s) repeated across blocks";
    if (!missing.empty())
        summary += "; " + std::to_string(missing.size()) +
                   " block(s) not computed yet (run the same command again to resume)";
    if (shard)
        summary = "share " + std::to_string(shard->index) + "/" + std::to_string(shard->count) +
                  ": " + summary;

    nlohmann::ordered_json report = std::move(parts.header);
    report["seed"] = request.at("seed");
    report["blocks"] = std::move(parts.blocks);
    report["found"] = parts.variants.size();
    report["variants"] = std::move(parts.variants);
    report["duplicates"] = std::move(duplicates);
    report["met"] = everyBlockMet && missing.empty() && report["duplicates"].empty() &&
                    static_cast<long long>(report["found"].get<std::size_t>()) == asked;
    if (!missing.empty()) report["partial"] = true;
    report["missing_blocks"] = missing;
    report["summary"] = summary;
    report["distinct_within"] = "block";
    report["smallest_pairwise_de00"] = smallest;
    report["evaluations"] = evaluations;
    report["archived"] = archived;
    report["output_renders"] = outputRenders;
    if (shard) report["shard"] = {{"index", shard->index}, {"count", shard->count}};
    return report;
}

std::string blockContactSheet(int block) {
    char name[64];
    std::snprintf(name, sizeof name, "contact_sheets/block_%03d.png", block);
    return name;
}

Status writeVariantBlock(const std::filesystem::path& dir, const MaterialFile& target,
                         const VariantSet& set, const VariantBlocks& plan, int block,
                         const Font& font, ImageMetric heatmapMetric) {
    const std::size_t first = std::size_t(plan.firstIndex(block));
    const std::size_t count = std::size_t(plan.count);
    if (auto written = writeVariantMembers(dir, target, set, first, count, heatmapMetric); !written)
        return written;
    const std::filesystem::path sheet = dir / blockContactSheet(block);
    std::error_code error;
    std::filesystem::create_directories(sheet.parent_path(), error);
    if (error)
        return badInput("cannot create folder '" + sheet.parent_path().string() + "' (" +
                        error.message() + ")");
    return writeImage(contactSheet(set, font, first, count), sheet);
}

}  // namespace matevo
