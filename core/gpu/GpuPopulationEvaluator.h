#pragma once
// Render + ΔE00 + heatmaps for a population in one GPU submission: the target and every
// candidate are rendered into one buffer, the ΔE00 pass compares each candidate with the
// target's render, and everything is read back. Used by `render`, `evolve --out`, the bench
// and the editor's grid. Buffers are kept between calls of the same shape.
#include <span>
#include <vector>

#include "color/ImageDifference.h"
#include "common/Image.h"
#include "common/Result.h"
#include "gpu/DeltaE00Pass.h"
#include "gpu/GpuContext.h"
#include "gpu/GpuImageComparer.h"
#include "gpu/GpuSphereRenderer.h"

namespace matevo::gpu {

struct PopulationEvaluation {
    Image target;
    std::vector<Image> candidates;
    std::vector<DeltaEMap> deltaE;  // candidate vs target, over pixels covered in both
    std::vector<Image> heatmaps;    // colormapped ΔE00, transparent where not covered
};

class GpuPopulationEvaluator {
public:
    // The device must outlive the evaluator.
    static Result<GpuPopulationEvaluator> create(const Device& device, const FgdTables& tables,
                                                 const SceneTextures& textures,
                                                 const DeltaE00Pass::Colormap& colormap);

    Result<PopulationEvaluation> evaluate(const MaterialInstance& target,
                                          std::span<const MaterialInstance> candidates,
                                          const SceneSettings& scene, int size,
                                          const HeatmapRange& range = {});

    // Renders only (no comparison), one submission.
    Result<std::vector<Image>> render(std::span<const MaterialInstance> materials,
                                      const SceneSettings& scene, int size);

private:
    Status ensureBuffers(const ImageBatchShape& shape);

    const Device* device_ = nullptr;
    CommandRunner runner_;
    GpuSphereRenderer renderer_;
    DeltaE00Pass deltaEPass_;
    ImageBatchShape bufferShape_;  // candidates only; renders_ holds one image more
    Buffer renders_;
    Buffer deltaE_;
    Buffer heatmaps_;
};

}  // namespace matevo::gpu
