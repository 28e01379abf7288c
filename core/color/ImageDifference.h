#pragma once
// Per-pixel CIEDE2000 between two renders of the same size and its pooled statistics over the
// pixels covered in both (alpha >= 0.5, color/Coverage.h), the paper's image-space error (§5).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/Image.h"
#include "common/Result.h"

namespace matevo {

// Over the covered pixels; all zero when no pixel is covered (check `pixels`).
struct DeltaEStats {
    double mean = 0;
    double max = 0;
    // Nearest-rank 95th percentile: the smallest ΔE00 that at least 95 % of the covered pixels do
    // not exceed, i.e. the ceil(0.95 N)-th smallest value.
    double p95 = 0;
    std::size_t pixels = 0;
};

struct DeltaEMap {
    int width = 0;
    int height = 0;
    std::vector<float> deltaE;          // row-major; 0 where not covered
    std::vector<std::uint8_t> covered;  // 1 where both images cover the pixel
    DeltaEStats stats;
};

// Ok when the two images have the same size and well-formed pixel data; otherwise an Error
// saying which sizes differ. Every image comparison checks this first.
Status requireComparable(const Image& a, const Image& b);

// Linear RGBA in, clamped to [0, 1] before conversion to L*a*b*. With useAlpha false (images that
// had no alpha channel) every pixel counts. Differing sizes give an Error. Work is split in fixed
// chunks over at most workerCount threads (0: workerThreadCount()); the result, down to the
// last bit, does not depend on how many threads ran.
Result<DeltaEMap> compareImages(const Image& a, const Image& b, bool useAlpha = true,
                                unsigned workerCount = 0);

}  // namespace matevo
