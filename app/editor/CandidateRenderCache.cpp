#include "CandidateRenderCache.h"

#include <algorithm>
#include "documents/PresetTextures.h"

namespace matevo::editor {
namespace {

// On lavapipe the window's frames wait behind the worker's work on the one queue: submissions
// of a few tiles keep a frame's wait short.
constexpr std::size_t kTilesPerSubmission = 8;

// The tiles' error maps are `heatmapMetric`'s; the window colours them itself.
EvaluationOptions evaluationOptions(ImageMetric heatmapMetric) {
    EvaluationOptions options;
    options.candidateImages = true;  // the inspector's readout
    options.flip = heatmapMetric == ImageMetric::Flip;
    options.heatmapMetric = heatmapMetric;
    return options;
}

}  // namespace

CandidateRenderCache::CandidateRenderCache(int tileSize, int targetSize, std::size_t capacity,
                                           const gpu::Device& device, gpu::RendererRequest request)
    : tileSize_(tileSize),
      targetSize_(targetSize),
      capacity_(capacity),
      device_(device),
      request_(std::move(request)) {
    request_.device = &device;
}

bool CandidateRenderCache::drawsTheSame(const Preset& preset,
                                        const std::filesystem::path& presetFile,
                                        ImageMetric heatmapMetric) const {
    return preset_ && presetFile == presetFile_ && heatmapMetric == heatmapMetric_ &&
           preset.target == preset_->target && preset.family == preset_->family &&
           preset.baseKappa == preset_->baseKappa && preset.scene == preset_->scene &&
           preset.roughnessTexture == preset_->roughnessTexture &&
           preset.baseColorTexture == preset_->baseColorTexture;
}

MaterialInstance CandidateRenderCache::material(const Genome& genome) const {
    return {genome, preset_->family, preset_->baseKappa};
}

Status CandidateRenderCache::useTexturesOf(const Preset& preset,
                                           const std::filesystem::path& presetFile) {
    const TextureSources sources = textureSourcesOf(preset, presetFile);
    if (renderer_ && textureSources_ == sources) return Ok{};
    textureSources_.reset();
    if (!uploadRunner_) {
        auto runner = gpu::CommandRunner::create(device_);
        if (!runner) return runner.error();
        uploadRunner_ = std::move(runner).value();
    }
    if (!renderer_) {
        auto created = gpu::createPresetRenderer(request_, preset, presetFile);
        if (!created) return created.error();
        renderer_ = std::move(created).value();
    } else {
        auto textures = loadSceneTextures(preset, presetFile);
        if (!textures) return textures.error();
        if (Status set = renderer_->setTextures(*textures); !set) return set;
    }
    textureSources_ = sources;
    return Ok{};
}

TileOutput CandidateRenderCache::tileOutput(std::span<const gpu::DisplayTile* const> tiles) {
    return {tiles, [this, tiles](std::span<const Image> pictures, std::span<const ErrorMap> maps) {
                return gpu::uploadToTiles(device_, *uploadRunner_, tiles, pictures, maps);
            }};
}

Status CandidateRenderCache::prepare(const Preset& preset, const std::filesystem::path& presetFile,
                                     ImageMetric heatmapMetric) {
    if (drawsTheSame(preset, presetFile, heatmapMetric)) return Ok{};
    if (Status ready = useTexturesOf(preset, presetFile); !ready) return ready;
    // lavapipe compiles the ꟻLIP pipelines at their first dispatch, holding the queue the window
    // draws on: one at a time, before any tile waits on them (docs/flip.md).
    if (Status compiled = renderer_->prepareFor(evaluationOptions(heatmapMetric)); !compiled)
        return compiled;
    entries_.clear();
    heatmapMetric_ = heatmapMetric;
    targetPicture_.reset();
    preset_.reset();  // nothing is cached for a half-prepared preset
    if (Status drawn = drawTarget(preset); !drawn) return drawn;
    preset_ = preset;
    presetFile_ = presetFile;
    return Ok{};
}

Status CandidateRenderCache::drawTarget(const Preset& preset) {
    auto tile = gpu::DisplayTile::create(device_, targetSize_, targetSize_, false);
    if (!tile) return tile.error();
    auto target = std::make_shared<gpu::DisplayTile>(std::move(tile).value());
    const MaterialInstance material{preset.target, preset.family, preset.baseKappa};
    const gpu::DisplayTile* tiles[] = {target.get()};
    if (Status drawn =
            renderer_->renderIntoTile(material, preset.scene, targetSize_, tileOutput(tiles));
        !drawn)
        return drawn;
    target_ = std::move(target);
    return Ok{};
}

CandidateRenderCache::Entry* CandidateRenderCache::find(const Genome& genome) {
    for (Entry& entry : entries_)
        if (entry.genome == genome) return &entry;
    return nullptr;
}

Status CandidateRenderCache::draw(std::span<const Genome> genomes) {
    std::vector<MaterialInstance> materials;
    std::vector<std::shared_ptr<gpu::DisplayTile>> tiles;
    std::vector<const gpu::DisplayTile*> targets;
    for (const Genome& genome : genomes) {
        auto tile = gpu::DisplayTile::create(device_, tileSize_, tileSize_, true);
        if (!tile) return tile.error();
        tiles.push_back(std::make_shared<gpu::DisplayTile>(std::move(tile).value()));
        targets.push_back(tiles.back().get());
        materials.push_back(material(genome));
    }
    const MaterialInstance target = material(preset_->target);
    auto evaluation =
        renderer_->evaluateIntoTiles(target, materials, preset_->scene, tileSize_,
                                     evaluationOptions(heatmapMetric_), tileOutput(targets));
    if (!evaluation) return evaluation.error();
    std::vector<ErrorMap>& deltaE = evaluation->errors.at(ImageMetric::DeltaE00);
    const auto flip = evaluation->errors.find(ImageMetric::Flip);
    if (!targetPicture_) targetPicture_ = std::make_shared<Image>(std::move(evaluation->target));
    for (std::size_t i = 0; i < genomes.size(); ++i) {
        const ErrorStats stats = deltaE[i].stats;
        entries_.push_back(
            {genomes[i],
             {tiles[i], stats, std::make_shared<Image>(std::move(evaluation->candidates[i])),
              std::make_shared<ErrorMap>(std::move(deltaE[i])),
              flip != evaluation->errors.end()
                  ? std::make_shared<ErrorMap>(std::move(flip->second[i]))
                  : nullptr},
             useCounter_});
    }
    return Ok{};
}

void CandidateRenderCache::evictBeyondCapacity() {
    // The least recently used first; never what the current request uses. A tile still shown
    // by the window stays alive there until it is replaced.
    std::sort(entries_.begin(), entries_.end(),
              [](const Entry& a, const Entry& b) { return a.lastUse > b.lastUse; });
    std::size_t keep = capacity_;
    while (keep < entries_.size() && entries_[keep].lastUse == useCounter_) ++keep;
    if (entries_.size() > keep) entries_.resize(keep);
}

Result<std::vector<CandidateTile>> CandidateRenderCache::tiles(std::span<const Genome> genomes,
                                                               const CancelToken& cancel) {
    if (!preset_) return internalError("no preset prepared");
    ++useCounter_;
    std::vector<Genome> missing;
    for (const Genome& genome : genomes) {
        if (Entry* entry = find(genome))
            entry->lastUse = useCounter_;
        else if (std::find(missing.begin(), missing.end(), genome) == missing.end())
            missing.push_back(genome);
    }
    for (std::size_t first = 0; first < missing.size(); first += kTilesPerSubmission) {
        if (cancel.cancelled()) return cancelledError("rendering cancelled");
        const std::size_t count = std::min(kTilesPerSubmission, missing.size() - first);
        if (Status drawn = draw(std::span(missing).subspan(first, count)); !drawn)
            return drawn.error();
    }
    evictBeyondCapacity();
    std::vector<CandidateTile> result;
    for (const Genome& genome : genomes) result.push_back(find(genome)->tile);
    return result;
}

}  // namespace matevo::editor
