#pragma once
// ΔE00 and heatmaps on the GPU for images that already exist on the host (e.g. CPU renders):
// upload, one submission of the compute pass, read back. The GPU renderer feeds the same pass
// straight from its own buffers instead.
#include <span>
#include <vector>

#include "color/ImageDifference.h"
#include "common/Image.h"
#include "common/Result.h"
#include "gpu/CommandRunner.h"
#include "gpu/DeltaE00Pass.h"

namespace matevo::gpu {

struct GpuComparison {
    std::vector<DeltaEMap> maps;  // one per candidate
    std::vector<Image> heatmaps;  // one per candidate; transparent where not covered
};

struct HeatmapRange {
    float minDeltaE = 0.0f;
    float maxDeltaE = 10.0f;
};

class GpuImageComparer {
public:
    static Result<GpuImageComparer> create(const Device& device,
                                           const DeltaE00Pass::Colormap& colormap);

    // Every candidate must have the reference's size.
    Result<GpuComparison> compare(const Image& reference, std::span<const Image> candidates,
                                  const HeatmapRange& range = {});

private:
    const Device* device_ = nullptr;
    DeltaE00Pass pass_;
    CommandRunner runner_;
};

}  // namespace matevo::gpu
