#include "variants/ShareResume.h"

#include <algorithm>

#include "files/InputFile.h"
#include "files/JsonReader.h"
#include "files/TextFile.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;

// The first key of `expected` whose value differs in `found`, as a dotted path ("request.seed").
std::optional<std::string> firstDifference(const nlohmann::ordered_json& expected,
                                           const nlohmann::ordered_json& found,
                                           const std::string& path) {
    if (expected.is_object() && found.is_object()) {
        for (const auto& [key, value] : expected.items()) {
            const std::string field = path.empty() ? key : path + "." + key;
            if (!found.contains(key)) return field;
            if (auto differs = firstDifference(value, found.at(key), field)) return differs;
        }
        if (found.size() != expected.size()) return path;
        return std::nullopt;
    }
    if (expected != found) return path;
    return std::nullopt;
}

std::optional<Shard> shardOf(const nlohmann::ordered_json& report) {
    if (!report.contains("shard")) return std::nullopt;
    return Shard{jsonInteger<int>(report.at("shard").at("index")),
                 jsonInteger<int>(report.at("shard").at("count"))};
}

}  // namespace

std::string shareName(const std::optional<Shard>& shard) {
    if (!shard) return "the set";
    return "share " + std::to_string(shard->index) + "/" + std::to_string(shard->count);
}

Result<ResumableBlocks> readResumableBlocks(const fs::path& folder, const BlockReport& header,
                                            const std::optional<Shard>& shard) {
    const fs::path file = folder / "report.json";
    auto text = readTextFile(file);
    if (!text) return text.error();
    // Through the depth check as every JSON matevo reads: a tampered report must not overflow
    // the parser's stack.
    auto parsed = parseJsonDocument<nlohmann::ordered_json>(*text, displayPath(file));
    if (!parsed) return parsed.error();
    const nlohmann::ordered_json& report = *parsed;
    auto fieldError = [&file](const std::string& field, const std::string& problem) {
        return badInput(displayPath(file) + ": " + field + ": " + problem);
    };
    if (!report.is_object()) return badInput(displayPath(file) + ": not a JSON object");
    ResumableBlocks kept;
    try {
        for (const auto& [field, expected] : header.header.items()) {
            if (!report.contains(field)) return fieldError(field, "missing");
            if (auto differs = firstDifference(expected, report.at(field), field))
                return fieldError(*differs,
                                  "differs from this run's: the folder holds another "
                                  "request (--force replaces it)");
        }
        if (const std::optional<Shard> found = shardOf(report);
            found.has_value() != shard.has_value() ||
            (found && (found->index != shard->index || found->count != shard->count)))
            return fieldError("shard", "the folder holds " + shareName(found) + ", this run is " +
                                           shareName(shard) + " (--force replaces it)");
        BlockReport parts{header.header, {}, {}};
        const std::vector<int> ofThisRun = missingBlocks(parts, shard);
        for (const auto& block : report.at("blocks")) {
            const int index = jsonInteger<int>(block.at("index"));
            if (std::find(ofThisRun.begin(), ofThisRun.end(), index) == ofThisRun.end())
                return fieldError("blocks", "block " + std::to_string(index) + " is not one of " +
                                                shareName(shard) + "'s");
            parts.blocks.push_back(block);
        }
        for (const auto& variant : report.at("variants")) {
            const int block = jsonInteger<int>(variant.at("block"));
            if (std::none_of(parts.blocks.begin(), parts.blocks.end(), [block](const auto& entry) {
                    return jsonInteger<int>(entry.at("index")) == block;
                }))
                return fieldError("variants", "variant " + variant.at("index").dump() +
                                                  " is not in a listed block");
            parts.variants.push_back(variant);
        }
        kept.missing = missingBlocks(parts, shard);
        kept.madeBy = report.value("made_by", nlohmann::ordered_json());
        kept.blocks = std::move(parts.blocks);
        kept.variants = std::move(parts.variants);
    } catch (const nlohmann::ordered_json::exception& error) {
        return fieldError("blocks/variants", error.what());
    }
    return kept;
}

}  // namespace matevo
