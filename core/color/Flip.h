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
#include "color/ErrorMap.h"
#include "color/FlipPooling.h"
#include "color/FlipStages.h"
#include "common/Image.h"
#include "common/Result.h"

namespace matevo {

struct FlipSettings {
    // The viewing condition: how many pixels one degree of visual angle spans.
    double pixelsPerDegree = flip::kDefaultPixelsPerDegree;
};

// An ErrorMap of ImageMetric::Flip (mean, weighted median and quartiles, max). Differing sizes
// give an Error. Multi-threaded over fixed row bands; the result does not depend on the thread
// count (workerCount: at most so many; 0: workerThreadCount()).
Result<ErrorMap> computeFlip(const Image& reference, const Image& test, bool useAlpha = true,
                             const FlipSettings& settings = {}, unsigned workerCount = 0);

}  // namespace matevo
