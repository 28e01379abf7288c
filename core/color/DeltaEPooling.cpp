#include "color/DeltaEPooling.h"

namespace matevo {

void DeltaEPooling::merge(const DeltaEPooling& later) {
    sum_ += later.sum_;
    max_ = std::max(max_, later.max_);
    pixels_ += later.pixels_;
    for (std::size_t bucket = 0; bucket < kBucketCount; ++bucket)
        histogram_[bucket] += later.histogram_[bucket];
}

ErrorStats DeltaEPooling::finish(std::span<const float> deltaE,
                                 std::span<const std::uint8_t> covered) const {
    ErrorStats stats;
    stats.pixels = pixels_;
    if (pixels_ == 0) return stats;
    stats.mean = sum_ / double(pixels_);
    stats.max = max_;
    // ceil(0.95 N) computed in integers: the 1-based rank.
    const std::size_t rank = (95 * pixels_ + 99) / 100;
    std::size_t bucket = 0, below = 0;
    for (; below + histogram_[bucket] < rank; ++bucket) below += histogram_[bucket];
    // Compacted without branches (one spare slot for the writes that do not count): which
    // pixels fall in the bucket is as unpredictable as the image.
    std::vector<float> candidates(histogram_[bucket] + 1);
    std::size_t found = 0;
    for (std::size_t i = 0; i < deltaE.size(); ++i) {
        candidates[found] = deltaE[i];
        const bool inBucket = bucketOf(deltaE[i]) == bucket;
        found += (covered[i] != 0) & inBucket;
    }
    candidates.pop_back();
    auto nth = candidates.begin() + std::ptrdiff_t(rank - below - 1);
    std::nth_element(candidates.begin(), nth, candidates.end());
    stats.p95 = *nth;
    return stats;
}

ErrorStats poolDeltaE(std::span<const float> deltaE, std::span<const std::uint8_t> covered) {
    DeltaEPooling pooling;
    for (std::size_t i = 0; i < deltaE.size(); ++i) pooling.add(deltaE[i], covered[i] != 0);
    return pooling.finish(deltaE, covered);
}

}  // namespace matevo
