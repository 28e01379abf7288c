#include "variants/ShardMerge.h"

#include <algorithm>
#include <string>

#include "documents/CarriedTextures.h"
#include "documents/MaterialFile.h"
#include "files/AtomicFile.h"
#include "files/InputFile.h"
#include "files/JsonReader.h"
#include "files/TextFile.h"
#include "variants/ShareResume.h"
#include "variants/VariantBlockFiles.h"
#include "variants/VariantBlocks.h"
#include "variants/VariantFiles.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;

struct ShareReport {
    fs::path folder;
    nlohmann::ordered_json report;
    Shard shard;
};

Error fieldError(const fs::path& folder, const std::string& field, const std::string& problem) {
    return badInput(displayPath(folder / "report.json") + ": " + field + ": " + problem);
}

Result<ShareReport> readShare(const fs::path& folder) {
    auto text = readTextFile(folder / "report.json");
    if (!text) return text.error();
    auto report =
        parseJsonDocument<nlohmann::ordered_json>(*text, displayPath(folder / "report.json"));
    if (!report) return report.error();
    ShareReport share{folder, std::move(*report), {}};
    if (!share.report.is_object())
        return badInput(displayPath(folder / "report.json") + ": not a JSON object");
    if (!share.report.contains("shard"))
        return fieldError(folder, "shard", "missing (not written by matevo variants --shard I/K)");
    try {
        for (const char* field : kBlockHeaderFields)
            if (!share.report.contains(field)) return fieldError(folder, field, "missing");
        share.shard = {jsonInteger<int>(share.report.at("shard").at("index")),
                       jsonInteger<int>(share.report.at("shard").at("count"))};
        for (const char* field : {"blocks", "variants"})
            if (!share.report.at(field).is_array())
                return fieldError(folder, field, "must be an array");
    } catch (const nlohmann::ordered_json::exception& error) {
        return fieldError(folder, "shard", error.what());
    }
    return share;
}

Status copyFile(const fs::path& from, const fs::path& to) {
    auto bytes = readInputFile(from, kMaxImageFileBytes);
    if (!bytes) return bytes.error();
    return writeFileAtomically(to, *bytes);
}

// A share's material file saved again in the merged set `dir`, its textures carried into the
// set (documents/CarriedTextures.h), so that the merged set does not depend on the shares' folders.
Status copyMaterial(const fs::path& from, const fs::path& dir, const fs::path& to) {
    auto loaded = loadMaterial(from, MaterialFile{});
    if (!loaded) return loaded.error();
    if (loaded->fromContext)
        return badInput(displayPath(from) + ": a bare genome, not a variant's material file");
    auto carried = carryTextures(loaded->file, dir);
    if (!carried) return carried.error();
    return saveMaterial(*carried, to);
}

// Copies the variants and contact sheets of one share into `dir`; checks that they are its own.
Status copyShare(const ShareReport& share, const VariantBlocks& plan, const fs::path& dir,
                 BlockReport& joined) {
    std::vector<int> blocks;
    try {
        for (const auto& block : share.report.at("blocks")) {
            blocks.push_back(jsonInteger<int>(block.at("index")));
            joined.blocks.push_back(block);
        }
        const std::vector<int> expected = blocksOfShard(plan, share.shard);
        if (blocks != expected) {
            const bool partial =
                std::includes(expected.begin(), expected.end(), blocks.begin(), blocks.end());
            if (partial)
                return fieldError(
                    share.folder, "blocks",
                    shareName(share.shard) + " is partial (" +
                        std::to_string(expected.size() - blocks.size()) + " of its " +
                        std::to_string(expected.size()) +
                        " blocks missing): resume it by running its `matevo variants ... --shard " +
                        std::to_string(share.shard.index) + "/" +
                        std::to_string(share.shard.count) + " --out " + displayPath(share.folder) +
                        "` again (add --resume to insist), then merge");
            return fieldError(share.folder, "blocks",
                              "not the blocks of " + shareName(share.shard));
        }
        for (const auto& variant : share.report.at("variants")) {
            const auto index = jsonInteger<int>(variant.at("index"));
            const int block = jsonInteger<int>(variant.at("block"));
            if (std::find(blocks.begin(), blocks.end(), block) == blocks.end() ||
                index < plan.firstIndex(block) ||
                index >= plan.firstIndex(block) + plan.countIn(block))
                return fieldError(
                    share.folder, "variants",
                    "variant " + std::to_string(index) + " is not in one of this share's blocks");
            const std::string stem =
                "variants/" + variantStem(std::size_t(index), std::size_t(plan.count));
            if (auto copied =
                    copyMaterial(share.folder / (stem + ".json"), dir, dir / (stem + ".json"));
                !copied)
                return copied;
            for (const char* suffix : {".png", "_heatmap.png"})
                if (auto copied = copyFile(share.folder / (stem + suffix), dir / (stem + suffix));
                    !copied)
                    return copied;
            joined.variants.push_back(variant);
        }
    } catch (const nlohmann::ordered_json::exception& error) {
        return fieldError(share.folder, "blocks/variants", error.what());
    }
    for (const int block : blocks)
        if (auto copied =
                copyFile(share.folder / blockContactSheet(block), dir / blockContactSheet(block));
            !copied)
            return copied;
    return Ok{};
}

// The lightings a share's set holds under; null for the preset's own scene.
nlohmann::ordered_json lightingsOf(const ShareReport& share) {
    const nlohmann::ordered_json& request = share.report.at("request");
    return request.is_object() ? request.value("lightings", nlohmann::ordered_json())
                               : nlohmann::ordered_json();
}

nlohmann::ordered_json madeByOf(const ShareReport& share) {
    return share.report.value("made_by", nlohmann::ordered_json());
}

// The shares' common "made_by"; the device lists each share's when they differ.
nlohmann::ordered_json joinedMadeBy(const std::vector<const ShareReport*>& shares) {
    nlohmann::ordered_json madeBy = madeByOf(*shares.front());
    std::vector<std::string> devices;
    for (const ShareReport* share : shares) {
        const nlohmann::ordered_json made = madeByOf(*share);
        const std::string device = made.is_object() ? made.value("device", "") : "";
        if (std::find(devices.begin(), devices.end(), device) == devices.end())
            devices.push_back(device);
    }
    std::string joined;
    for (const std::string& device : devices) joined += (joined.empty() ? "" : "; ") + device;
    madeBy["device"] = joined;
    return madeBy;
}

}  // namespace

Result<nlohmann::ordered_json> mergeShards(const std::vector<fs::path>& folders,
                                           const fs::path& dir) {
    if (folders.empty()) return badInput("no share folders given");
    std::vector<ShareReport> shares;
    for (const fs::path& folder : folders) {
        auto share = readShare(folder);
        if (!share) return share.error();
        shares.push_back(std::move(*share));
    }
    const ShareReport& first = shares.front();
    const int shareCount = first.shard.count;
    VariantBlocks plan;
    try {
        plan = {jsonInteger<int>(first.report.at("request").at("count")),
                jsonInteger<int>(first.report.at("request").at("block"))};
    } catch (const nlohmann::ordered_json::exception& error) {
        return fieldError(first.folder, "request", error.what());
    }
    if (plan.count < 1 || plan.blockSize < 1 || shareCount < 1)
        return fieldError(first.folder, "request", "count, block and shares must be at least 1");

    std::vector<const ShareReport*> byIndex(std::size_t(shareCount), nullptr);
    for (const ShareReport& share : shares) {
        if (lightingsOf(share) != lightingsOf(first))
            return fieldError(share.folder, "request.lightings",
                              lightingsOf(share).dump() + " differs from " +
                                  displayPath(first.folder) + "'s " + lightingsOf(first).dump() +
                                  ": shares searched under different lightings are never merged");
        for (const char* field : kBlockHeaderFields)
            if (share.report[field] != first.report[field])
                return fieldError(share.folder, field,
                                  "differs from " + displayPath(first.folder) +
                                      "'s: the shares are not of one request");
        if (auto conflict = madeByConflict(madeByOf(share), madeByOf(first)))
            return fieldError(share.folder, *conflict,
                              madeByOf(share).dump() + " differs from " +
                                  displayPath(first.folder) + "'s " + madeByOf(first).dump() +
                                  ": shares of different back ends or versions are never merged");
        if (share.shard.count != shareCount || share.shard.index < 0 ||
            share.shard.index >= shareCount)
            return fieldError(share.folder, "shard",
                              std::to_string(share.shard.index) + "/" +
                                  std::to_string(share.shard.count) + " is not a share of " +
                                  std::to_string(shareCount));
        const ShareReport*& slot = byIndex[std::size_t(share.shard.index)];
        if (slot)
            return fieldError(share.folder, "shard",
                              "share " + std::to_string(share.shard.index) + " is also in " +
                                  displayPath(slot->folder));
        slot = &share;
    }
    for (int index = 0; index < shareCount; ++index)
        if (!byIndex[std::size_t(index)])
            return badInput("share " + std::to_string(index) + "/" + std::to_string(shareCount) +
                            " is missing");

    auto target = readInputFile(first.folder / "target.png", kMaxImageFileBytes);
    if (!target) return target.error();
    for (const ShareReport* share : byIndex) {
        auto bytes = readInputFile(share->folder / "target.png", kMaxImageFileBytes);
        if (!bytes) return bytes.error();
        if (*bytes != *target)
            return badInput(displayPath(share->folder / "target.png") + ": differs from " +
                            displayPath(first.folder / "target.png") +
                            " (rendered by another back end or version?)");
    }

    for (const fs::path& folder : {dir / "variants", (dir / blockContactSheet(0)).parent_path()}) {
        std::error_code error;
        fs::create_directories(folder, error);
        if (error)
            return badInput("cannot create folder '" + folder.string() + "' (" + error.message() +
                            ")");
    }
    BlockReport joined;
    for (const char* field : kBlockHeaderFields) joined.header[field] = first.report[field];
    if (first.report.contains("made_by")) joined.header["made_by"] = joinedMadeBy(byIndex);
    for (const ShareReport* share : byIndex)
        if (auto copied = copyShare(*share, plan, dir, joined); !copied) return copied.error();
    if (auto written = writeFileAtomically(dir / "target.png", *target); !written)
        return written.error();
    // The target's material file, from a share that holds a block (a share without one wrote
    // no material).
    for (const ShareReport* share : byIndex) {
        if (!fs::exists(targetMaterialFile(share->folder))) continue;
        if (auto copied =
                copyMaterial(targetMaterialFile(share->folder), dir, targetMaterialFile(dir));
            !copied)
            return copied.error();
        break;
    }
    nlohmann::ordered_json report = assembleBlockReport(std::move(joined), std::nullopt);
    if (auto written = writeFileAtomically(dir / "report.json", report.dump(2) + "\n"); !written)
        return written.error();
    return report;
}

}  // namespace matevo
