#pragma once
// Pools a ΔE00 map into its statistics (ErrorStats: mean, max and nearest-rank 95th percentile
// over the covered pixels), one pixel at a time, in chunks that merge. The CPU comparison
// (compareImages) and the GPU paths' read-back pool through it, so both give the same figures.
//
// The 95th percentile without sorting: non-negative floats order like their bit patterns, so
// their top bits (exponent and three mantissa bits: an eighth of an octave) sort ΔE00 values
// into ordered buckets, counted as pixels are added. The percentile then needs ordering only
// within the one bucket that holds it.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "color/ImageDifference.h"

namespace matevo {

class DeltaEPooling {
public:
    // Branch-free (coverage along a sphere's rim is hard to predict): an uncovered pixel adds
    // nothing. `deltaE` is non-negative.
    void add(float deltaE, bool covered) {
        const float value = covered ? deltaE : 0.0f;
        sum_ += value;
        max_ = std::max(max_, value);
        histogram_[bucketOf(value)] += covered ? 1 : 0;
        pixels_ += covered ? 1 : 0;
    }
    // Adds another chunk's pixels after this one's (sums in that order).
    void merge(const DeltaEPooling& later);
    // The statistics of the pixels added; the p95 reads the values of its bucket back from the
    // whole map they came from.
    ErrorStats finish(std::span<const float> deltaE, std::span<const std::uint8_t> covered) const;

private:
    static constexpr int kBucketShift = 20;
    static constexpr std::size_t kBucketCount = std::size_t(1) << (31 - kBucketShift);
    static std::size_t bucketOf(float deltaE) {
        return std::min(std::size_t(std::bit_cast<std::uint32_t>(deltaE) >> kBucketShift),
                        kBucketCount - 1);
    }

    double sum_ = 0.0;
    float max_ = 0.0f;
    std::size_t pixels_ = 0;
    std::vector<std::uint32_t> histogram_ = std::vector<std::uint32_t>(kBucketCount, 0);
};

// One map's statistics, pooled in pixel order.
ErrorStats poolDeltaE(std::span<const float> deltaE, std::span<const std::uint8_t> covered);

}  // namespace matevo
