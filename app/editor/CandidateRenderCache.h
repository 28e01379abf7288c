#pragma once
// Renders candidate tiles and their ΔE00 maps against the target into DisplayTiles on the
// window's device, and remembers them across generations and across GA re-runs while the
// picture's inputs (target, family, kappa, scene, textures) stay the same. The best candidates
// mostly survive from one generation to the next, and a re-run with the same seed starts from
// much the same population, so most tiles of an update are already drawn. New tiles are drawn
// by the render interface; on the GPU straight into the tiles (render + ΔE00 + copies in one
// submission, nothing read back but the error maps for their statistics and the inspector's
// readout). When the heatmap shows ꟻLIP, the tiles' error maps hold ꟻLIP instead, computed in
// the same submission on the same device.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "color/ImageDifference.h"
#include "common/CancelToken.h"
#include "common/Result.h"
#include "documents/Preset.h"
#include "documents/PresetTextures.h"
#include "gpu/CommandRunner.h"
#include "gpu/DisplayTile.h"
#include "gpu/PopulationRendererFactory.h"
#include "render/PopulationRenderer.h"
#include "scene/SceneTextures.h"

namespace matevo::editor {

struct CandidateTile {
    std::shared_ptr<const gpu::DisplayTile> tile;  // render + ΔE00 map, on the window's device
    ErrorStats stats;                              // of the ΔE00 map
    // Host copies, for the inspector's readout of the pixel under the pointer.
    std::shared_ptr<const Image> picture;
    std::shared_ptr<const ErrorMap> deltaE;
    std::shared_ptr<const ErrorMap> flip;  // with a ꟻLIP heatmap
};

class CandidateRenderCache {
public:
    // Tiles live on `device` (the window's), which must outlive the cache. `request` chooses
    // the renderer (its device is set to `device`); it is made at the first prepare.
    CandidateRenderCache(int tileSize, int targetSize, std::size_t capacity,
                         const gpu::Device& device, gpu::RendererRequest request);

    // Serves `preset` from now on, with tiles whose heatmaps show `heatmapMetric`; forgets
    // everything if the picture's inputs or the metric changed. The target is rendered here,
    // once per change; the textures are read again only when their files change, so a change
    // of the target keeps the renderer's textures and pipelines.
    Status prepare(const Preset& preset, const std::filesystem::path& presetFile,
                   ImageMetric heatmapMetric = ImageMetric::DeltaE00);
    const std::shared_ptr<const gpu::DisplayTile>& target() const { return target_; }
    // The target at tile size, as the ΔE00 maps compare against it; null before the first tiles.
    const std::shared_ptr<const Image>& targetPicture() const { return targetPicture_; }
    // The tiles of `genomes`, in order; cancelledError() when `cancel` is cancelled before a
    // submission.
    Result<std::vector<CandidateTile>> tiles(std::span<const Genome> genomes,
                                             const CancelToken& cancel = {});
    // "GPU (llvmpipe)" or "CPU", for the status line; empty before the first prepare.
    std::string backendName() const { return renderer_ ? renderer_->name() : std::string(); }

private:
    struct Entry {
        Genome genome;
        CandidateTile tile;
        std::uint64_t lastUse = 0;
    };
    bool drawsTheSame(const Preset& preset, const std::filesystem::path& presetFile,
                      ImageMetric heatmapMetric) const;
    MaterialInstance material(const Genome& genome) const;
    Status useTexturesOf(const Preset& preset, const std::filesystem::path& presetFile);
    TileOutput tileOutput(std::span<const gpu::DisplayTile* const> tiles);
    Status drawTarget(const Preset& preset);
    Status draw(std::span<const Genome> genomes);
    Entry* find(const Genome& genome);
    void evictBeyondCapacity();

    int tileSize_;
    int targetSize_;
    std::size_t capacity_;
    const gpu::Device& device_;
    gpu::RendererRequest request_;
    std::unique_ptr<PopulationRenderer> renderer_;
    std::optional<TextureSources> textureSources_;  // what the renderer's textures were read from
    // Uploads host pictures into tiles, for a renderer that draws elsewhere (the CPU's).
    std::optional<gpu::CommandRunner> uploadRunner_;
    ImageMetric heatmapMetric_ = ImageMetric::DeltaE00;
    std::optional<Preset> preset_;  // what the cached pictures were drawn from
    std::filesystem::path presetFile_;
    std::shared_ptr<const gpu::DisplayTile> target_;
    std::shared_ptr<const Image> targetPicture_;
    std::vector<Entry> entries_;
    std::uint64_t useCounter_ = 0;
};

}  // namespace matevo::editor
