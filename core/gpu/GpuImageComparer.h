#pragma once
// ΔE00 or ꟻLIP and heatmaps on the GPU for images that already exist on the host (e.g. CPU
// renders): upload, one submission of the compute pass, read back. The GPU renderer feeds the
// same passes straight from its own buffers instead.
#include <span>
#include <vector>

#include "color/Flip.h"
#include "color/ImageDifference.h"
#include "common/Image.h"
#include "common/Result.h"
#include "gpu/CommandRunner.h"
#include "gpu/DeltaE00Pass.h"
#include "gpu/FlipPass.h"
#include "gpu/ImageBatch.h"

namespace matevo::gpu {

struct GpuComparison {
    std::vector<DeltaEMap> maps;  // one per candidate
    std::vector<Image> heatmaps;  // one per candidate; transparent where not covered
};

struct GpuFlipComparison {
    std::vector<FlipMap> maps;    // one per candidate
    std::vector<Image> heatmaps;  // one per candidate, magma; transparent where not pooled
};

struct HeatmapRange {
    float minDeltaE = 0.0f;
    float maxDeltaE = 10.0f;
};

class GpuImageComparer {
public:
    // `colormap` colours ΔE00 over the range given to compare; ꟻLIP is always magma.
    static Result<GpuImageComparer> create(const Device& device,
                                           const DeltaE00Pass::Colormap& colormap);

    // Every candidate must have the reference's size.
    Result<GpuComparison> compare(const Image& reference, std::span<const Image> candidates,
                                  const HeatmapRange& range = {});
    Result<GpuFlipComparison> compareFlip(const Image& reference, std::span<const Image> candidates,
                                          const FlipSettings& settings = {});

private:
    // The images in upload buffers, and read-back buffers for one map and one heatmap per
    // candidate: kept from call to call, made anew only for a larger batch. (Fresh buffers at
    // every call cost a page fault per 4 KiB touched, or not, as the C library's allocator
    // happened to hand out memory: at 256² that was up to four times the ΔE00 pass's time.)
    struct Buffers {
        Buffer reference, candidates, maps, heatmaps;
    };
    // Copies the images into buffers_ (made or grown first when needed).
    Result<ImageBatchShape> upload(const Image& reference, std::span<const Image> candidates);

    const Device* device_ = nullptr;
    DeltaE00Pass deltaEPass_;
    FlipPass flipPass_;
    CommandRunner runner_;
    Buffers buffers_;
};

}  // namespace matevo::gpu
