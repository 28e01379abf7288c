#pragma once
// Per-pixel CIEDE2000 between two renders of the same size (an ErrorMap of ImageMetric::DeltaE00:
// mean, max and p95) and its pooled statistics over the pixels covered in both (alpha >= 0.5,
// color/Coverage.h), the paper's image-space error (§5).
#include "color/ErrorMap.h"
#include "common/Image.h"
#include "common/Result.h"

namespace matevo {

// Ok when the two images have the same size and well-formed pixel data; otherwise an Error
// saying which sizes differ. Every image comparison checks this first.
Status requireComparable(const Image& a, const Image& b);

// Linear RGBA in, clamped to [0, 1] before conversion to L*a*b*. With useAlpha false (images that
// had no alpha channel) every pixel counts. Differing sizes give an Error. Work is split in fixed
// chunks over at most workerCount threads (0: workerThreadCount()); the result, down to the
// last bit, does not depend on how many threads ran.
Result<ErrorMap> compareImages(const Image& a, const Image& b, bool useAlpha = true,
                               unsigned workerCount = 0);

}  // namespace matevo
