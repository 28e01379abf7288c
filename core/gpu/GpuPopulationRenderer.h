#pragma once
// The render interface on Vulkan: the target and every candidate are rendered by
// GpuSphereRenderer, the ΔE00 pass (and, when asked, the ꟻLIP pass) compares each candidate
// with the target's render, and everything is read back, in one submission. The target's render
// stays in its own buffer until the target changes. Buffers are kept between calls of the same
// shape.
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "common/CancelToken.h"
#include "common/Result.h"
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
    static Result<std::unique_ptr<GpuPopulationRenderer>> create(const Device& device,
                                                                 const FgdTables& tables,
                                                                 const SceneTextures& textures,
                                                                 CancelToken cancel = {});
    // Renders on a headless device of its own.
    static Result<std::unique_ptr<GpuPopulationRenderer>> createHeadless(
        const GpuContextOptions& options, const FgdTables& tables, const SceneTextures& textures,
        CancelToken cancel = {});

    std::string name() const override;
    RenderBackend backend() const override { return RenderBackend::Gpu; }
    Status setTextures(const SceneTextures& textures) override;
    Result<std::vector<Image>> render(std::span<const MaterialInstance> materials,
                                      const SceneSettings& scene, int size) override;
    Result<PopulationEvaluation> evaluate(const MaterialInstance& target,
                                          std::span<const MaterialInstance> candidates,
                                          const SceneSettings& scene, int size,
                                          const EvaluationOptions& options = {}) override;

    // On the tiles' device (this renderer's): the renders and error maps are copied into the
    // tiles in the evaluation's own submission, nothing uploaded from the host.
    Result<PopulationEvaluation> evaluateIntoTiles(const MaterialInstance& target,
                                                   std::span<const MaterialInstance> candidates,
                                                   const SceneSettings& scene, int size,
                                                   const EvaluationOptions& options,
                                                   const TileOutput& tiles) override;
    // Compiles the ꟻLIP pipelines when `options` want ꟻLIP (FlipPass::compile).
    Status prepareFor(const EvaluationOptions& options) override;
    Status renderIntoTile(const MaterialInstance& material, const SceneSettings& scene, int size,
                          const TileOutput& tile) override;

private:
    GpuPopulationRenderer() = default;
    Status ensureFlipPass();
    Status ensureBuffers(const ImageBatchShape& shape, bool flip);
    Status renderTarget(const TargetKey& key);
    Result<PopulationEvaluation> evaluateOnDevice(const MaterialInstance& target,
                                                  std::span<const MaterialInstance> candidates,
                                                  const SceneSettings& scene, int size,
                                                  const EvaluationOptions& options,
                                                  std::span<const DisplayTile* const> tiles);

    // Declared first, destroyed last: everything below lives on its device.
    std::unique_ptr<GpuContext> ownContext_;
    const Device* device_ = nullptr;
    const FgdTables* tables_ = nullptr;
    CancelToken cancel_;
    CommandRunner runner_;
    GpuSphereRenderer renderer_;
    std::optional<FlipPass> flipPass_;  // made when first asked for (lavapipe compiles it then)
    std::optional<TargetKey> targetKey_;
    Image target_;  // the host copy of targetRender_
    Buffer targetRender_;
    TexelBuffer targetLab_;  // target_ in L*a*b*, with its alpha: what each render compares with
    ImageBatchShape bufferShape_;
    // The coverage whose background renders_ and deltaE_ already hold (the fills
    // are skipped while it stays the same); none after the buffers are made.
    std::optional<GpuSphereSamples::Key> backgroundFilledFor_;
    Buffer renders_;
    Buffer deltaE_;
    // The ꟻLIP pass's maps, of bufferShape_ when ꟻLIP was asked for.
    Buffer flip_;
};

}  // namespace matevo::gpu
