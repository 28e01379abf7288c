#include "CandidateRenderCache.h"

#include <algorithm>

namespace matevo::editor {

CandidateRenderCache::CandidateRenderCache(int tileSize, int targetSize, std::size_t capacity,
                                           gpu::RendererRequest request)
    : tileSize_(tileSize),
      targetSize_(targetSize),
      capacity_(capacity),
      request_(std::move(request)) {}

bool CandidateRenderCache::drawsTheSame(const Preset& preset,
                                        const std::filesystem::path& presetFile) const {
    return preset_ && presetFile == presetFile_ && preset.target == preset_->target &&
           preset.family == preset_->family && preset.baseKappa == preset_->baseKappa &&
           preset.scene == preset_->scene && preset.roughnessTexture == preset_->roughnessTexture &&
           preset.baseColorTexture == preset_->baseColorTexture;
}

MaterialInstance CandidateRenderCache::material(const Genome& genome) const {
    return {genome, preset_->family, preset_->baseKappa};
}

Status CandidateRenderCache::prepare(const Preset& preset,
                                     const std::filesystem::path& presetFile) {
    if (drawsTheSame(preset, presetFile)) return Ok{};
    auto textures = loadSceneTextures(preset, presetFile);
    if (!textures) return textures.error();
    if (!renderer_)
        renderer_ = gpu::createPopulationRenderer(request_, *textures);
    else if (auto set = renderer_->setTextures(*textures); !set)
        return set.error();
    entries_.clear();
    preset_.reset();  // nothing is cached for a half-prepared preset
    const MaterialInstance target{preset.target, preset.family, preset.baseKappa};
    auto large = renderer_->render(std::span(&target, 1), preset.scene, targetSize_);
    if (!large) return large.error();
    target_ = std::move(large->front());
    preset_ = preset;
    presetFile_ = presetFile;
    return Ok{};
}

CandidateRenderCache::Entry* CandidateRenderCache::find(const Genome& genome) {
    for (Entry& entry : entries_)
        if (entry.genome == genome) return &entry;
    return nullptr;
}

Status CandidateRenderCache::draw(const std::vector<Genome>& genomes) {
    std::vector<MaterialInstance> materials;
    for (const Genome& genome : genomes) materials.push_back(material(genome));
    EvaluationOptions options;
    options.heatmaps = false;  // the editor colours the ΔE00 maps itself, in the user's range
    auto evaluation = renderer_->evaluate(material(preset_->target), materials, preset_->scene,
                                          tileSize_, options);
    if (!evaluation) return evaluation.error();
    for (std::size_t i = 0; i < genomes.size(); ++i)
        entries_.push_back(
            {genomes[i],
             {std::move(evaluation->candidates[i]), std::move(evaluation->deltaE[i])},
             useCounter_});
    return Ok{};
}

void CandidateRenderCache::evictBeyondCapacity() {
    // The least recently used first; never what the current request uses.
    std::sort(entries_.begin(), entries_.end(),
              [](const Entry& a, const Entry& b) { return a.lastUse > b.lastUse; });
    std::size_t keep = capacity_;
    while (keep < entries_.size() && entries_[keep].lastUse == useCounter_) ++keep;
    if (entries_.size() > keep) entries_.resize(keep);
}

Result<std::vector<CandidateTile>> CandidateRenderCache::tiles(std::span<const Genome> genomes) {
    if (!preset_) return Error{"no preset prepared"};
    ++useCounter_;
    std::vector<Genome> missing;
    for (const Genome& genome : genomes) {
        if (Entry* entry = find(genome))
            entry->lastUse = useCounter_;
        else if (std::find(missing.begin(), missing.end(), genome) == missing.end())
            missing.push_back(genome);
    }
    if (!missing.empty())
        if (auto drawn = draw(missing); !drawn) return drawn.error();
    evictBeyondCapacity();
    std::vector<CandidateTile> result;
    for (const Genome& genome : genomes) result.push_back(find(genome)->tile);
    return result;
}

}  // namespace matevo::editor
