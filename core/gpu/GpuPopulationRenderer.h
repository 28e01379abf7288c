#pragma once
// The render interface on Vulkan: the target and every candidate are rendered by
// GpuSphereRenderer, the ΔE00 pass (and, when asked, the ꟻLIP pass) compares each candidate
// with the target's render and colours the heatmaps, and everything is read back, in one
// submission. The target's render stays in
// its own buffer until the target changes. Buffers are kept between calls of the same shape.
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "common/CancelToken.h"
#include "common/Result.h"
#include "gpu/DeltaE00Pass.h"
#include "gpu/DisplayTile.h"
#include "gpu/FlipPass.h"
#include "gpu/GpuContext.h"
#include "gpu/GpuSphereRenderer.h"
#include "render/PopulationRenderer.h"

namespace matevo::gpu {

class GpuPopulationRenderer final : public PopulationRenderer {
public:
    // Renders on `device`, which must outlive the renderer. `tables` too (the process-wide
    // defaultFgdTables() does). `cancel` is checked before each submission; once it is
    // cancelled a call ends with cancelledError().
    static Result<std::unique_ptr<GpuPopulationRenderer>> create(
        const Device& device, const FgdTables& tables, const SceneTextures& textures,
        const DeltaE00Pass::Colormap& colormap, CancelToken cancel = {});
    // Renders on a headless device of its own.
    static Result<std::unique_ptr<GpuPopulationRenderer>> createHeadless(
        const GpuContextOptions& options, const FgdTables& tables, const SceneTextures& textures,
        const DeltaE00Pass::Colormap& colormap, CancelToken cancel = {});

    std::string name() const override;
    RenderBackend backend() const override { return RenderBackend::Gpu; }
    Status setTextures(const SceneTextures& textures) override;
    Result<std::vector<Image>> render(std::span<const MaterialInstance> materials,
                                      const SceneSettings& scene, int size) override;
    Result<PopulationEvaluation> evaluate(const MaterialInstance& target,
                                          std::span<const MaterialInstance> candidates,
                                          const SceneSettings& scene, int size,
                                          const EvaluationOptions& options = {}) override;

    // For a window on the same device: as evaluate, and in the same submission candidate i's
    // render and error map are copied into tiles[i] (one per candidate, size x size). The map is
    // the ꟻLIP one when options.heatmapMetric is ꟻLIP and options.flip computes it (e where
    // pooled, −1 − e elsewhere: negative, "not covered", as ΔE00's −1), else the ΔE00 one.
    Result<PopulationEvaluation> evaluateIntoTiles(const MaterialInstance& target,
                                                   std::span<const MaterialInstance> candidates,
                                                   const SceneSettings& scene, int size,
                                                   const EvaluationOptions& options,
                                                   std::span<const DisplayTile* const> tiles);
    // Has the ꟻLIP pipelines compiled now, one submission each (FlipPass::compile): the editor's
    // worker calls it before its first ꟻLIP tiles, so that the window's frames on the same
    // queue wait for one compile at a time.
    Status compileFlip(const FlipSettings& settings = {});
    // Renders one material into the tile's render image (tile size x tile size).
    Status renderIntoTile(const MaterialInstance& material, const SceneSettings& scene,
                          const DisplayTile& tile);

private:
    GpuPopulationRenderer() = default;
    Status ensureFlipPass();
    Status ensureBuffers(const ImageBatchShape& shape, bool flip);
    Status renderTarget(const TargetKey& key);

    // Declared first, destroyed last: everything below lives on its device.
    std::unique_ptr<GpuContext> ownContext_;
    const Device* device_ = nullptr;
    const FgdTables* tables_ = nullptr;
    CancelToken cancel_;
    CommandRunner runner_;
    GpuSphereRenderer renderer_;
    TexelBuffer heatmapColormap_;
    std::optional<FlipPass> flipPass_;  // made when first asked for (lavapipe compiles it then)
    std::optional<TargetKey> targetKey_;
    Image target_;  // the host copy of targetRender_
    Buffer targetRender_;
    TexelBuffer targetLab_;  // target_ in L*a*b*, with its alpha: what each render compares with
    ImageBatchShape bufferShape_;
    // The coverage whose background renders_, deltaE_ and heatmaps_ already hold (the fills
    // are skipped while it stays the same); none after the buffers are made.
    std::optional<GpuSphereSamples::Key> backgroundFilledFor_;
    Buffer renders_;
    Buffer deltaE_;
    Buffer heatmaps_;
    // The ꟻLIP pass's maps and heatmaps, of bufferShape_ when ꟻLIP was asked for.
    Buffer flip_;
    Buffer flipHeatmaps_;
};

}  // namespace matevo::gpu
