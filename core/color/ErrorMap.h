#pragma once
// A per-pixel error map between two renders of the same size, whichever ImageMetric made it
// (compareImages for ΔE00, computeFlip for ꟻLIP, or their GPU passes), with its statistics
// pooled over the pixels both renders cover. Callers pass maps around and pick them by metric,
// so a metric is one more ImageMetric value, not one more field everywhere.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "color/ImageMetric.h"

namespace matevo {

// Over the pooled pixels; all zero when there are none (check `pixels`). Each metric fills the
// figures it reports (those of the other stay zero).
struct ErrorStats {
    double mean = 0;
    double max = 0;
    std::size_t pixels = 0;
    // ΔE00: the nearest-rank 95th percentile, the smallest ΔE00 that at least 95 % of the
    // pixels do not exceed, i.e. the ceil(0.95 N)-th smallest value.
    double p95 = 0;
    // ꟻLIP: percentiles weighting each pixel by its own error, as the ꟻLIP authors pool: the
    // weighted median is the smallest error e such that pixels with error ≤ e carry more than
    // half of the summed error.
    double weightedMedian = 0;
    double firstWeightedQuartile = 0;
    double thirdWeightedQuartile = 0;
    bool operator==(const ErrorStats&) const = default;
};

struct ErrorMap {
    ImageMetric metric = ImageMetric::DeltaE00;
    int width = 0;
    int height = 0;
    // Row-major. Outside `covered`: 0 for ΔE00, the error all the same for ꟻLIP (whose filters
    // see the silhouette against the background).
    std::vector<float> values;
    std::vector<std::uint8_t> covered;  // 1 where the pixel counts in `stats`
    ErrorStats stats;
};

}  // namespace matevo
