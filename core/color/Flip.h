#pragma once
// LDR-ꟻLIP (Andersson et al. 2020) between two renders: a per-pixel error map in [0, 1] that,
// unlike per-pixel ΔE00, sees spatial structure (the eye's contrast sensitivity blurs fine
// detail; edges and points that appear or vanish count extra). The stages are in
// FlipStages.h. The CPU implementation here is the reference for the GPU pass.
//
// Input: linear RGBA, composited over black (RGB × alpha, the picture on a black background)
// and clamped to [0, 1]. The error is computed over the whole image — the filters see the
// silhouette against the background — and pooled over the same pixels as ΔE00: those both
// images cover (alpha >= 0.5, color/Coverage.h), or every pixel with useAlpha false.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "color/FlipPooling.h"
#include "color/FlipStages.h"
#include "common/Image.h"
#include "common/Result.h"

namespace matevo {

struct FlipSettings {
    // The viewing condition: how many pixels one degree of visual angle spans.
    double pixelsPerDegree = flip::kDefaultPixelsPerDegree;
};

struct FlipMap {
    int width = 0;
    int height = 0;
    std::vector<float> error;           // row-major, every pixel (also outside the pooled set)
    std::vector<std::uint8_t> pooled;   // 1 where the pixel counts in the statistics
    FlipStats stats;
};

// Differing sizes give an Error. Multi-threaded over fixed row bands; the result does not
// depend on the thread count (workerCount: at most so many; 0: workerThreadCount()).
Result<FlipMap> computeFlip(const Image& reference, const Image& test, bool useAlpha = true,
                            const FlipSettings& settings = {}, unsigned workerCount = 0);

}  // namespace matevo
