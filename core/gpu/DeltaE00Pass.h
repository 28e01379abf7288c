#pragma once
// The ΔE00 compute pass (shaders/DeltaE00.comp): one reference image against a batch of
// candidates, all linear RGBA float buffers laid out like Image::rgba, one image after another.
// Writes per-pixel ΔE00 (-1 where either alpha < 0.5).
#include <cstdint>

#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/ComputeKernel.h"

namespace matevo::gpu {

struct DeltaE00Batch {
    const Buffer* reference = nullptr;   // holds the reference image at referenceImage
    const Buffer* candidates = nullptr;  // holds the candidates from firstCandidate on
    const Buffer* deltaE = nullptr;      // candidateCount * pixelCount floats, written
    uint32_t pixelCount = 0;
    uint32_t candidateCount = 0;
    uint32_t referenceImage = 0;
    uint32_t firstCandidate = 0;
};

class DeltaE00Pass {
public:
    static Result<DeltaE00Pass> create(const Device& device);

    // Records the pass into commands; the caller adds barriers around it.
    void record(VkCommandBuffer commands, const DeltaE00Batch& batch) const;

private:
    ComputeKernel kernel_;
};

}  // namespace matevo::gpu
