#include "color/FlipPooling.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "common/ParallelFor.h"

namespace matevo {
namespace {

constexpr int kMantissaBits = 23;
// Pixels per chunk of the search for the errors in the percentiles' buckets.
constexpr std::size_t kChunkPixels = std::size_t(1) << 16;

}  // namespace

std::size_t FlipPooling::bucketOf(float error) {
    return std::size_t(std::bit_cast<std::uint32_t>(error) >> kBucketShift);
}

void FlipPooling::add(float error, bool pooled) {
    const float value = pooled ? std::clamp(error, 0.0f, 1.0f) : 0.0f;
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    const std::uint32_t exponent = bits >> kMantissaBits;
    // The implicit leading 1 of a normal float; subnormals (exponent 0) have none.
    const std::uint32_t significand =
        (bits & ((1u << kMantissaBits) - 1)) | (exponent != 0 ? 1u << kMantissaBits : 0u);
    significandSums_[bucketOf(value)] += significand;
    pixels_ += pooled ? 1 : 0;
    max_ = std::max(max_, value);
}

void FlipPooling::merge(const FlipPooling& other) {
    for (std::size_t bucket = 0; bucket < kBucketCount; ++bucket)
        significandSums_[bucket] += other.significandSums_[bucket];
    pixels_ += other.pixels_;
    max_ = std::max(max_, other.max_);
}

void FlipPooling::clear() {
    std::fill(significandSums_.begin(), significandSums_.end(), 0);
    pixels_ = 0;
    max_ = 0;
}

double FlipPooling::bucketSum(std::size_t bucket) const {
    // A float is significand × 2^(exponent − 150), the exponent of subnormals counting as 1.
    // Most buckets are empty, and ldexp is slow enough that a walk over all of them showed.
    const std::uint64_t sum = significandSums_[bucket];
    if (sum == 0) return 0.0;
    const int exponent = int(bucket >> (kMantissaBits - kBucketShift));
    return std::ldexp(double(sum), std::max(exponent, 1) - 150);
}

ErrorStats FlipPooling::finish(std::span<const float> errors, std::span<const std::uint8_t> pooled,
                               unsigned workerCount) const {
    ErrorStats stats;
    stats.pixels = pixels_;
    if (pixels_ == 0) return stats;
    double total = 0;
    for (std::size_t bucket = 0; bucket < kBucketCount; ++bucket) total += bucketSum(bucket);
    stats.mean = total / double(pixels_);
    stats.max = max_;
    // The smallest error at which the running sum, in ascending order, passes fraction · total:
    // the quartiles' buckets in one walk over the buckets (the thresholds ascend), their values
    // in one pass over the errors, then each bucket sorted.
    constexpr std::array<double, 3> kFractions = {0.25, 0.5, 0.75};
    std::array<std::size_t, 3> bucketOfQuartile{};
    std::array<double, 3> belowBucket{};
    double below = 0;
    std::size_t bucket = 0;
    for (std::size_t q = 0; q < kFractions.size(); ++q) {
        const double threshold = kFractions[q] * total;
        while (bucket + 1 < kBucketCount && below + bucketSum(bucket) <= threshold)
            below += bucketSum(bucket++);
        bucketOfQuartile[q] = bucket;
        belowBucket[q] = below;
    }
    using InBucket = std::array<std::vector<float>, 3>;
    const std::size_t chunkCount = (errors.size() + kChunkPixels - 1) / kChunkPixels;
    std::vector<InBucket> chunks(chunkCount);
    parallelForChunks(
        int(chunkCount),
        [&](int chunk) {
            const std::size_t first = std::size_t(chunk) * kChunkPixels;
            const std::size_t end = std::min(errors.size(), first + kChunkPixels);
            for (std::size_t i = first; i < end; ++i) {
                if (pooled[i] == 0) continue;
                const float error = std::clamp(errors[i], 0.0f, 1.0f);
                const std::size_t errorBucket = bucketOf(error);
                for (std::size_t q = 0; q < kFractions.size(); ++q)
                    if (errorBucket == bucketOfQuartile[q])
                        chunks[std::size_t(chunk)][q].push_back(error);
            }
        },
        {}, workerCount);
    InBucket inBucket;
    for (const InBucket& chunk : chunks)
        for (std::size_t q = 0; q < kFractions.size(); ++q)
            inBucket[q].insert(inBucket[q].end(), chunk[q].begin(), chunk[q].end());
    std::array<double, 3> quartiles{};  // 0 when every error is 0
    for (std::size_t q = 0; q < kFractions.size(); ++q) {
        std::sort(inBucket[q].begin(), inBucket[q].end());
        double running = belowBucket[q];
        for (float error : inBucket[q]) {
            running += error;
            if (running > kFractions[q] * total) {
                quartiles[q] = error;
                break;
            }
        }
    }
    stats.firstWeightedQuartile = quartiles[0];
    stats.weightedMedian = quartiles[1];
    stats.thirdWeightedQuartile = quartiles[2];
    return stats;
}

ErrorStats poolFlip(std::span<const float> errors, std::span<const std::uint8_t> pooled) {
    FlipPooling pooling;
    for (std::size_t i = 0; i < errors.size(); ++i) pooling.add(errors[i], pooled[i] != 0);
    return pooling.finish(errors, pooled);
}

}  // namespace matevo
