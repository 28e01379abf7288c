#pragma once
// The statistics of a ꟻLIP error map, gathered chunk by chunk on any number of threads: the
// errors are summed exactly (in integers, per bucket of equal float exponent), so the result
// does not depend on which thread added which pixels or in which order chunks are merged.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "color/ErrorMap.h"

namespace matevo {

class FlipPooling {
public:
    // Branch-free (which pixels count follows a render's silhouette): an unpooled pixel adds
    // nothing. `error` is clamped to [0, 1], ꟻLIP's range.
    void add(float error, bool pooled);
    void merge(const FlipPooling& other);
    // As new, without allocating.
    void clear();
    // The statistics of the pixels added; the percentiles read the errors of their buckets
    // back from the whole map they came from, on up to workerCount threads (0: all).
    ErrorStats finish(std::span<const float> errors, std::span<const std::uint8_t> pooled,
                      unsigned workerCount = 1) const;

private:
    // Non-negative floats order like their bit patterns: the top bits (exponent and seven
    // mantissa bits) sort errors into ordered buckets, so a weighted percentile needs sorting
    // only within the one (small) bucket where the running sum passes it.
    static constexpr int kBucketShift = 16;
    static constexpr std::size_t kBucketCount = (0x3f800000u >> kBucketShift) + 1;  // to 1.0f
    static std::size_t bucketOf(float error);
    // The summed errors of a bucket: its errors share one exponent, so their significands
    // (24-bit integers) add exactly, in any order, while fewer than 2^29 are summed.
    double bucketSum(std::size_t bucket) const;

    std::vector<std::uint64_t> significandSums_ = std::vector<std::uint64_t>(kBucketCount, 0);
    std::size_t pixels_ = 0;
    float max_ = 0;
};

// One map's statistics (errors and pooled flags pixel by pixel).
ErrorStats poolFlip(std::span<const float> errors, std::span<const std::uint8_t> pooled);

}  // namespace matevo
