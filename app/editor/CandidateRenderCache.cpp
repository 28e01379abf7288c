#include "CandidateRenderCache.h"

#include <algorithm>

#include "scene/SphereRenderer.h"

namespace matevo::editor {

CandidateRenderCache::CandidateRenderCache(int tileSize, int targetSize, std::size_t capacity)
    : tileSize_(tileSize), targetSize_(targetSize), capacity_(capacity) {}

bool CandidateRenderCache::drawsTheSame(const Preset& preset,
                                        const std::filesystem::path& presetFile) const {
    return preset_ && presetFile == presetFile_ && preset.target == preset_->target &&
           preset.family == preset_->family && preset.baseKappa == preset_->baseKappa &&
           preset.scene == preset_->scene &&
           preset.roughnessTexture == preset_->roughnessTexture &&
           preset.baseColorTexture == preset_->baseColorTexture;
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
    target_ = render(preset.target, targetSize_);
    targetTile_ = render(preset.target, tileSize_);
    return Ok{};
}

Image CandidateRenderCache::render(const Genome& genome, int size) const {
    const MaterialInstance material{genome, preset_->family, preset_->baseKappa};
    return renderSphereCpu(material, textures_, preset_->scene, size);
}

CandidateTile CandidateRenderCache::tile(const Genome& genome) {
    ++useCounter_;
    for (Entry& entry : entries_) {
        if (entry.genome == genome) {
            entry.lastUse = useCounter_;
            return entry.tile;
        }
    }
    CandidateTile drawn{render(genome, tileSize_), {}};
    if (auto deltaE = compareImages(targetTile_, drawn.image)) drawn.deltaE = std::move(*deltaE);
    if (entries_.size() >= capacity_) {
        const auto oldest = std::min_element(
            entries_.begin(), entries_.end(),
            [](const Entry& a, const Entry& b) { return a.lastUse < b.lastUse; });
        entries_.erase(oldest);
    }
    entries_.push_back({genome, drawn, useCounter_});
    return drawn;
}

}  // namespace matevo::editor
