#pragma once
// Renders candidate tiles and their ΔE00 maps against the target, and remembers them across
// generations and across GA re-runs while the picture's inputs (target, family, kappa, scene,
// textures) stay the same. The best candidates mostly survive from one generation to the next,
// and a re-run with the same seed starts from much the same population, so most tiles of an
// update are already drawn. New tiles are drawn in one batch by the render interface (on the
// GPU: render + ΔE00 in one submission).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "color/ImageDifference.h"
#include "common/Image.h"
#include "common/Result.h"
#include "gpu/PopulationRendererFactory.h"
#include "io/Preset.h"

namespace matevo::editor {

struct CandidateTile {
    Image image;
    DeltaEMap deltaE;
};

class CandidateRenderCache {
public:
    // `request` chooses the renderer, which is made at the first prepare (it needs textures).
    CandidateRenderCache(int tileSize, int targetSize, std::size_t capacity,
                         gpu::RendererRequest request);

    // Serves `preset` from now on; forgets everything if the picture's inputs changed.
    Status prepare(const Preset& preset, const std::filesystem::path& presetFile);
    const Image& target() const { return target_; }
    // The tiles of `genomes`, in order (an Error too when the request's `cancelled` said so).
    Result<std::vector<CandidateTile>> tiles(std::span<const Genome> genomes);
    // "GPU (llvmpipe)" or "CPU", for the status line; empty before the first prepare.
    std::string backendName() const { return renderer_ ? renderer_->name() : std::string(); }

private:
    struct Entry {
        Genome genome;
        CandidateTile tile;
        std::uint64_t lastUse = 0;
    };
    bool drawsTheSame(const Preset& preset, const std::filesystem::path& presetFile) const;
    MaterialInstance material(const Genome& genome) const;
    Status draw(const std::vector<Genome>& genomes);
    Entry* find(const Genome& genome);
    void evictBeyondCapacity();

    int tileSize_;
    int targetSize_;
    std::size_t capacity_;
    gpu::RendererRequest request_;
    std::unique_ptr<PopulationRenderer> renderer_;
    std::optional<Preset> preset_;  // what the cached pictures were drawn from
    std::filesystem::path presetFile_;
    Image target_;
    std::vector<Entry> entries_;
    std::uint64_t useCounter_ = 0;
};

}  // namespace matevo::editor
