#pragma once
// Renders candidate tiles and their ΔE00 maps against the target, and remembers them across
// generations and across GA re-runs while the picture's inputs (target, family, kappa, scene,
// textures) stay the same. The best candidates mostly survive from one generation to the next,
// and a re-run with the same seed starts from much the same population, so most tiles of an
// update are already drawn.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "color/ImageDifference.h"
#include "common/Image.h"
#include "common/Result.h"
#include "io/Preset.h"
#include "scene/SceneTextures.h"

namespace matevo::editor {

struct CandidateTile {
    Image image;
    DeltaEMap deltaE;
};

class CandidateRenderCache {
public:
    CandidateRenderCache(int tileSize, int targetSize, std::size_t capacity);

    // Serves `preset` from now on; forgets everything if the picture's inputs changed.
    Status prepare(const Preset& preset, const std::filesystem::path& presetFile);
    const Image& target() const { return target_; }
    CandidateTile tile(const Genome& genome);

private:
    struct Entry {
        Genome genome;
        CandidateTile tile;
        std::uint64_t lastUse = 0;
    };
    bool drawsTheSame(const Preset& preset, const std::filesystem::path& presetFile) const;
    Image render(const Genome& genome, int size) const;

    int tileSize_;
    int targetSize_;
    std::size_t capacity_;
    std::optional<Preset> preset_;  // what the cached pictures were drawn from
    std::filesystem::path presetFile_;
    SceneTextures textures_;
    Image target_;
    Image targetTile_;
    std::vector<Entry> entries_;
    std::uint64_t useCounter_ = 0;
};

}  // namespace matevo::editor
