#pragma once
// The LDR-ꟻLIP compute passes (shaders/FlipRowFilter.comp, then shaders/FlipCombine.comp):
// one reference image against a batch of candidates, all linear RGBA float buffers laid out
// like Image::rgba, as the ΔE00 pass takes them. Writes per-pixel ꟻLIP and a magma heatmap.
// core/color/Flip is the reference these passes follow step by step (tests/gpu compares them).
#include <cstdint>

#include "color/Flip.h"
#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/ComputeKernel.h"
#include "gpu/DeltaE00Pass.h"

namespace matevo::gpu {

struct FlipBatch {
    const Buffer* reference = nullptr;   // holds the reference image at referenceImage
    const Buffer* candidates = nullptr;  // holds the candidates from firstCandidate on
    // candidateCount * width * height floats, written: the error e where both images cover
    // the pixel (alpha >= 0.5), −1 − e elsewhere (downloadFlipMap reads it).
    const Buffer* error = nullptr;
    const Buffer* heatmaps = nullptr;  // candidateCount * width * height RGBA, written
    int width = 0;
    int height = 0;
    uint32_t candidateCount = 0;
    uint32_t referenceImage = 0;
    uint32_t firstCandidate = 0;
};

class FlipPass {
public:
    // `colormap` colours [0, 1] (magma: flipColormap()).
    static Result<FlipPass> create(const Device& device, const DeltaE00Pass::Colormap& colormap);

    // Records both passes and the barrier between them; the caller adds barriers around. The
    // pass's own buffers (the row-filtered planes, the filter taps) follow the batch and the
    // viewing condition, so any earlier submission of this pass must have completed.
    Status record(VkCommandBuffer commands, const FlipBatch& batch, const FlipSettings& settings);

private:
    Status prepare(const FlipBatch& batch, const FlipSettings& settings);

    const Device* device_ = nullptr;
    Buffer colormap_;
    ComputeKernel rowFilter_;
    ComputeKernel combine_;
    Buffer taps_;
    double tapsPixelsPerDegree_ = 0;
    flip::CsfKernels csf_;
    flip::FeatureKernels feature_;
    Buffer planes_;
};

}  // namespace matevo::gpu
