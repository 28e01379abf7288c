#pragma once
// The LDR-ꟻLIP compute passes (shaders/FlipRowFilter.comp, then shaders/FlipCombine.comp):
// one reference image against a batch of candidates, all linear RGBA float buffers laid out
// like Image::rgba, as the ΔE00 pass takes them. Writes per-pixel ꟻLIP.
// core/color/Flip is the reference these passes follow step by step (tests/gpu compares them).
// The passes unroll their filters for the viewing condition's radii, and lavapipe's compile
// time grows with them (uncached, in CPU time at load 9: about 1.8 s at the default 67 pixels
// per degree, 3.6 s at 148): they take filter radii up to 20 pixels, about 148 pixels per degree,
// and refuse wider ones with an error (the CPU path takes any). lavapipe compiles a pipeline
// at its first dispatch, on the queue that runs it: work on the same queue waits that long.
// The passes store 64-bit words (fewer stores, which lavapipe makes lane by lane), so they need
// a device with shaderInt64 (lavapipe and desktop GPUs have it; create refuses others).
#include <cstdint>
#include <vector>

#include "color/Flip.h"
#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/CommandRunner.h"
#include "gpu/ComputeKernel.h"

namespace matevo::gpu {

// The images' buffers come from createBatchBuffer: the pass reads them as texel buffers.
struct FlipBatch {
    const Buffer* reference = nullptr;   // holds the reference image at referenceImage
    const Buffer* candidates = nullptr;  // holds the candidates from firstCandidate on
    // candidateCount * width * height floats, written: the error e where both images cover
    // the pixel (alpha >= 0.5), −1 − e elsewhere (downloadErrorMap reads it).
    const Buffer* error = nullptr;
    int width = 0;
    int height = 0;
    uint32_t candidateCount = 0;
    uint32_t referenceImage = 0;
    uint32_t firstCandidate = 0;
};

class FlipPass {
public:
    static Result<FlipPass> create(const Device& device);

    // Records both passes and the barrier between them; the caller adds barriers around. The
    // pass's own buffers (the row-filtered planes, the filter taps) follow the batch and the
    // viewing condition, so any earlier submission of this pass must have completed.
    Status record(VkCommandBuffer commands, const FlipBatch& batch, const FlipSettings& settings);

    // Makes the pipelines for the viewing condition and has lavapipe compile them now, each in a
    // submission of its own on `runner` (one dispatch over one pixel), and waits: work of other
    // threads on the same queue (the editor's frames) then waits for one compile at a time,
    // not for both and a batch's passes (seconds with a cold shader cache, docs/flip.md).
    Status compile(CommandRunner& runner, const FlipSettings& settings = {});

private:
    // The shaders specialised for one pair of filter radii (a viewing condition).
    struct Kernels {
        int csfRadius = 0;
        int featureRadius = 0;
        ComputeKernel rowFilter;
        ComputeKernel combine;
    };

    Status prepare(const FlipBatch& batch, const FlipSettings& settings);
    // Prepares for the batch and binds its buffers to the viewing condition's kernels.
    Result<const Kernels*> bind(const FlipBatch& batch, const FlipSettings& settings);
    // `buffer` as vec4 texels: lavapipe fetches texels for all SIMD lanes in one go, where it
    // loads a storage buffer at a per-invocation index one lane and component at a time.
    Result<UniqueBufferView> pixelView(const Buffer& buffer) const;
    // The kernels for the current radii, made on first use and kept: lavapipe takes seconds
    // to compile the unrolled filters.
    Result<const Kernels*> kernelsFor(int csfRadius, int featureRadius);

    const Device* device_ = nullptr;
    std::vector<Kernels> kernels_;
    Buffer taps_;
    double tapsPixelsPerDegree_ = 0;
    flip::CsfKernels csf_;
    flip::FeatureKernels feature_;
    Buffer planes_;
    UniqueBufferView planesView_;
    // The batch's images, made by prepare for each record.
    UniqueBufferView referenceView_;
    UniqueBufferView candidatesView_;
};

}  // namespace matevo::gpu
