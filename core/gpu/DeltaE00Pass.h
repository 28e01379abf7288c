#pragma once
// The ΔE00 + heatmap compute pass (shaders/DeltaE00Heatmap.comp): one reference image against
// a batch of candidates, all linear RGBA float buffers laid out like Image::rgba, one image
// after another. Writes per-pixel ΔE00 (-1 where either alpha < 0.5) and heatmap RGBA.
#include <array>
#include <cstdint>
#include <span>

#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/ComputeKernel.h"

namespace matevo::gpu {

struct DeltaE00Batch {
    const Buffer* reference = nullptr;   // holds the reference image at referenceImage
    const Buffer* candidates = nullptr;  // holds the candidates from firstCandidate on
    const Buffer* deltaE = nullptr;      // candidateCount * pixelCount floats, written
    const Buffer* heatmaps = nullptr;    // candidateCount * pixelCount RGBA, written
    uint32_t pixelCount = 0;
    uint32_t candidateCount = 0;
    uint32_t referenceImage = 0;
    uint32_t firstCandidate = 0;
    float minDeltaE = 0.0f;  // maps to the first colormap entry
    float maxDeltaE = 10.0f;  // maps to the last
};

class DeltaE00Pass {
public:
    static constexpr std::size_t kColormapSize = 256;
    using Colormap = std::array<std::array<float, 4>, kColormapSize>;  // linear RGBA

    static Result<DeltaE00Pass> create(const Device& device, const Colormap& colormap);

    // Records the pass into commands; the caller adds barriers around it.
    void record(VkCommandBuffer commands, const DeltaE00Batch& batch) const;

private:
    Buffer colormap_;
    ComputeKernel kernel_;
};

// A colour map in a storage buffer, as the heatmap shaders read it (vec4 colormap[256]).
Result<Buffer> createColormapBuffer(const Device& device, const DeltaE00Pass::Colormap& colormap);

}  // namespace matevo::gpu
