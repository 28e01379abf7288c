#include "CandidateRenderCache.h"

#include <cstdio>

#include <algorithm>

#include "color/Colormap.h"
#include "material/FgdTableCache.h"
#include "scene/SphereRenderer.h"

namespace matevo::editor {
namespace {

// The GPU pass also colours heatmaps; the editor re-colours from the ΔE00 maps when the range
// changes, so it only needs the same colour map as core/color.
gpu::DeltaE00Pass::Colormap viridis() {
    gpu::DeltaE00Pass::Colormap colormap{};
    for (std::size_t i = 0; i < colormap.size(); ++i) {
        const auto rgb = colormapLinear(double(i) / double(colormap.size() - 1));
        colormap[i] = {rgb[0], rgb[1], rgb[2], 1.0f};
    }
    return colormap;
}

}  // namespace

CandidateRenderCache::CandidateRenderCache(int tileSize, int targetSize, std::size_t capacity,
                                           bool useGpu, bool validation)
    : tileSize_(tileSize), targetSize_(targetSize), capacity_(capacity) {
    if (!useGpu) return;
    auto context = gpu::GpuContext::createHeadless({validation, true});
    if (context)
        gpu_ = std::make_unique<gpu::GpuContext>(std::move(*context));
    else
        std::fprintf(stderr, "matevo edit: notice: tiles render on the CPU (%s)\n",
                     context.error().message.c_str());
}

CandidateRenderCache::~CandidateRenderCache() = default;

std::string CandidateRenderCache::backendName() const {
    return evaluator_ ? "GPU (" + gpu_->device.name() + ")" : "CPU";
}

int CandidateRenderCache::validationMessages() const {
    if (!gpu_) return 0;
    const gpu::ValidationLog& log = gpu_->instance.validationLog();
    return log.errorCount() + log.warningCount();
}

bool CandidateRenderCache::drawsTheSame(const Preset& preset,
                                        const std::filesystem::path& presetFile) const {
    return preset_ && presetFile == presetFile_ && preset.target == preset_->target &&
           preset.family == preset_->family && preset.baseKappa == preset_->baseKappa &&
           preset.scene == preset_->scene && preset.roughnessTexture == preset_->roughnessTexture &&
           preset.baseColorTexture == preset_->baseColorTexture;
}

void CandidateRenderCache::createGpuEvaluator() {
    evaluator_.reset();
    if (!gpu_) return;
    auto evaluator =
        gpu::GpuPopulationEvaluator::create(gpu_->device, defaultFgdTables(), textures_, viridis());
    if (evaluator) evaluator_.emplace(std::move(*evaluator));
}

Status CandidateRenderCache::prepare(const Preset& preset,
                                     const std::filesystem::path& presetFile) {
    if (drawsTheSame(preset, presetFile)) return Ok{};
    auto textures = loadSceneTextures(preset, presetFile);
    if (!textures) return textures.error();
    preset_ = preset;
    presetFile_ = presetFile;
    textures_ = std::move(*textures);
    entries_.clear();
    createGpuEvaluator();
    target_ = renderOne(preset.target, targetSize_);
    targetTile_ = renderOne(preset.target, tileSize_);
    return Ok{};
}

Image CandidateRenderCache::renderOne(const Genome& genome, int size) {
    const MaterialInstance material{genome, preset_->family, preset_->baseKappa};
    if (evaluator_) {
        auto images = evaluator_->render(std::span(&material, 1), preset_->scene, size);
        if (images) return std::move(images->front());
        evaluator_.reset();  // the device failed: the CPU draws from now on
    }
    return renderSphereCpu(material, textures_, preset_->scene, size);
}

CandidateRenderCache::Entry* CandidateRenderCache::find(const Genome& genome) {
    for (Entry& entry : entries_)
        if (entry.genome == genome) return &entry;
    return nullptr;
}

bool CandidateRenderCache::drawOnGpu(const std::vector<Genome>& genomes) {
    const MaterialInstance target{preset_->target, preset_->family, preset_->baseKappa};
    std::vector<MaterialInstance> materials;
    for (const Genome& genome : genomes)
        materials.push_back({genome, preset_->family, preset_->baseKappa});
    auto evaluation = evaluator_->evaluate(target, materials, preset_->scene, tileSize_);
    if (!evaluation) {
        evaluator_.reset();
        return false;
    }
    for (std::size_t i = 0; i < genomes.size(); ++i)
        entries_.push_back(
            {genomes[i],
             {std::move(evaluation->candidates[i]), std::move(evaluation->deltaE[i])},
             useCounter_});
    return true;
}

bool CandidateRenderCache::drawOnCpu(const std::vector<Genome>& genomes,
                                     const std::function<bool()>& cancelled) {
    for (const Genome& genome : genomes) {
        if (cancelled()) return false;
        CandidateTile tile{renderOne(genome, tileSize_), {}};
        if (auto deltaE = compareImages(targetTile_, tile.image)) tile.deltaE = std::move(*deltaE);
        entries_.push_back({genome, std::move(tile), useCounter_});
    }
    return true;
}

void CandidateRenderCache::evictBeyondCapacity() {
    // The least recently used first; never what the current request uses.
    std::sort(entries_.begin(), entries_.end(),
              [](const Entry& a, const Entry& b) { return a.lastUse > b.lastUse; });
    std::size_t keep = capacity_;
    while (keep < entries_.size() && entries_[keep].lastUse == useCounter_) ++keep;
    if (entries_.size() > keep) entries_.resize(keep);
}

std::optional<std::vector<CandidateTile>> CandidateRenderCache::tiles(
    std::span<const Genome> genomes, const std::function<bool()>& cancelled) {
    ++useCounter_;
    std::vector<Genome> missing;
    for (const Genome& genome : genomes) {
        if (Entry* entry = find(genome))
            entry->lastUse = useCounter_;
        else if (std::find(missing.begin(), missing.end(), genome) == missing.end())
            missing.push_back(genome);
    }
    if (!missing.empty() && !(evaluator_ && drawOnGpu(missing)) && !drawOnCpu(missing, cancelled))
        return std::nullopt;
    evictBeyondCapacity();
    std::vector<CandidateTile> result;
    for (const Genome& genome : genomes) result.push_back(find(genome)->tile);
    return result;
}

}  // namespace matevo::editor
