#include "color/Flip.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "color/Coverage.h"
#include "color/ImageDifference.h"
#include "color/detail/ForEachChunk.h"

namespace matevo {
namespace {

// Rows per band of work. A band filters the rows it needs along x (its own plus the filter
// radius above and below) into band-local buffers, then along y: more rows per band repeat
// less of the row pass, fewer keep the buffers in cache.
constexpr int kBandRows = 64;

// One image in YyCxCz, a plane per channel, and the achromatic channel normalised to [0, 1]
// for the feature detectors.
struct OpponentPlanes {
    std::vector<float> achromatic, redGreen, blueYellow, lightness;
};

OpponentPlanes toOpponentPlanes(const Image& image) {
    const std::size_t count = image.pixelCount();
    OpponentPlanes planes{std::vector<float>(count), std::vector<float>(count),
                          std::vector<float>(count), std::vector<float>(count)};
    for (std::size_t i = 0; i < count; ++i) {
        const float* pixel = &image.rgba[4 * i];
        const float alpha = std::clamp(pixel[3], 0.0f, 1.0f);  // over black
        const flip::Ycxcz color =
            flip::linearSrgbToYcxcz(pixel[0] * alpha, pixel[1] * alpha, pixel[2] * alpha);
        planes.achromatic[i] = color.y;
        planes.redGreen[i] = color.cx;
        planes.blueYellow[i] = color.cz;
        planes.lightness[i] = (color.y + 16.0f) / 116.0f;
    }
    return planes;
}

// out[x] = Σ_k taps[k] in[clamp(x + k − radius)]: the row copied with repeated edges, then
// one multiply-add sweep per tap (which the compiler vectorises).
void filterRow(const float* in, int width, const std::vector<float>& taps, float* padded,
               float* out) {
    const int radius = int(taps.size() / 2);
    for (int i = 0; i < width + 2 * radius; ++i) padded[i] = in[std::clamp(i - radius, 0, width - 1)];
    std::fill(out, out + width, 0.0f);
    for (std::size_t k = 0; k < taps.size(); ++k) {
        const float tap = taps[k];
        const float* shifted = padded + k;
        for (int x = 0; x < width; ++x) out[x] += tap * shifted[x];
    }
}

// The row pass of one band: rows [first, first + count) of the image (clamped at its edges)
// for one plane, filtered along x with `taps`, stored consecutively.
class RowFiltered {
public:
    RowFiltered(int width, int first, int count) : width_(width), first_(first),
        rows_(std::size_t(width) * std::size_t(count)) {}

    void fill(const std::vector<float>& plane, int height, const std::vector<float>& taps,
              std::vector<float>& padded) {
        const int count = int(rows_.size() / std::size_t(width_));
        for (int i = 0; i < count; ++i) {
            const int y = std::clamp(first_ + i, 0, height - 1);
            filterRow(&plane[std::size_t(y) * width_], width_, taps, padded.data(),
                      &rows_[std::size_t(i) * width_]);
        }
    }
    // The stored row for image row y (first_ ≤ y < first_ + count).
    const float* row(int y) const { return &rows_[std::size_t(y - first_) * width_]; }

private:
    int width_, first_;
    std::vector<float> rows_;
};

// out[x] += Σ_k taps[k] rows.row(y + k − radius)[x].
void filterColumns(const RowFiltered& rows, int y, const std::vector<float>& taps, int width,
                   float* out) {
    const int radius = int(taps.size() / 2);
    for (std::size_t k = 0; k < taps.size(); ++k) {
        const float tap = taps[k];
        const float* row = rows.row(y + int(k) - radius);
        for (int x = 0; x < width; ++x) out[x] += tap * row[x];
    }
}

struct Kernels {
    flip::CsfKernels csf;
    flip::FeatureKernels feature;
};

// The colour error (step 3) of one band's rows.
void colorErrorOfBand(const OpponentPlanes& reference, const OpponentPlanes& test, int width,
                      int height, int firstRow, int endRow, const flip::CsfKernels& csf,
                      float* colorError) {
    const int radius = csf.radius;
    const int first = firstRow - radius, count = endRow - firstRow + 2 * radius;
    std::vector<float> padded(std::size_t(width + 2 * radius));
    struct Filtered {
        RowFiltered achromatic, redGreen, blueYellow0, blueYellow1;
    };
    auto rowPass = [&](const OpponentPlanes& planes) {
        Filtered filtered{RowFiltered(width, first, count), RowFiltered(width, first, count),
                          RowFiltered(width, first, count), RowFiltered(width, first, count)};
        filtered.achromatic.fill(planes.achromatic, height, csf.achromatic, padded);
        filtered.redGreen.fill(planes.redGreen, height, csf.redGreen, padded);
        filtered.blueYellow0.fill(planes.blueYellow, height, csf.blueYellow[0], padded);
        filtered.blueYellow1.fill(planes.blueYellow, height, csf.blueYellow[1], padded);
        return filtered;
    };
    const Filtered rowsReference = rowPass(reference);
    const Filtered rowsTest = rowPass(test);

    // Columns, clamped at the image's edges: a band's stored rows already repeat them.
    std::vector<float> sums(std::size_t(width) * 6);
    for (int y = firstRow; y < endRow; ++y) {
        std::fill(sums.begin(), sums.end(), 0.0f);
        float* out[6];
        for (int c = 0; c < 6; ++c) out[c] = &sums[std::size_t(c) * width];
        filterColumns(rowsReference.achromatic, y, csf.achromatic, width, out[0]);
        filterColumns(rowsReference.redGreen, y, csf.redGreen, width, out[1]);
        filterColumns(rowsReference.blueYellow0, y, csf.blueYellow[0], width, out[2]);
        filterColumns(rowsReference.blueYellow1, y, csf.blueYellow[1], width, out[2]);
        filterColumns(rowsTest.achromatic, y, csf.achromatic, width, out[3]);
        filterColumns(rowsTest.redGreen, y, csf.redGreen, width, out[4]);
        filterColumns(rowsTest.blueYellow0, y, csf.blueYellow[0], width, out[5]);
        filterColumns(rowsTest.blueYellow1, y, csf.blueYellow[1], width, out[5]);
        for (int x = 0; x < width; ++x)
            colorError[std::size_t(y) * width + x] = flip::colorDifference(
                {out[0][x], out[1][x], out[2][x]}, {out[3][x], out[4][x], out[5][x]});
    }
}

// The feature error (step 4) of one band's rows, combined with its colour error (step 5).
void flipOfBand(const OpponentPlanes& reference, const OpponentPlanes& test, int width,
                int height, int firstRow, int endRow, const flip::FeatureKernels& feature,
                float* error) {
    const int radius = feature.radius;
    const int first = firstRow - radius, count = endRow - firstRow + 2 * radius;
    std::vector<float> padded(std::size_t(width + 2 * radius));
    struct Filtered {
        RowFiltered slope, curvature, blurred;  // along x: first, second derivative, Gaussian
    };
    auto rowPass = [&](const OpponentPlanes& planes) {
        Filtered filtered{RowFiltered(width, first, count), RowFiltered(width, first, count),
                          RowFiltered(width, first, count)};
        filtered.slope.fill(planes.lightness, height, feature.firstDerivative, padded);
        filtered.curvature.fill(planes.lightness, height, feature.secondDerivative, padded);
        filtered.blurred.fill(planes.lightness, height, feature.gaussian, padded);
        return filtered;
    };
    const Filtered rowsReference = rowPass(reference);
    const Filtered rowsTest = rowPass(test);

    std::vector<float> sums(std::size_t(width) * 8);
    for (int y = firstRow; y < endRow; ++y) {
        std::fill(sums.begin(), sums.end(), 0.0f);
        float* out[8];
        for (int c = 0; c < 8; ++c) out[c] = &sums[std::size_t(c) * width];
        const Filtered* images[2] = {&rowsReference, &rowsTest};
        for (int image = 0; image < 2; ++image) {
            float* const* o = out + 4 * image;
            filterColumns(images[image]->slope, y, feature.gaussian, width, o[0]);      // ∂x
            filterColumns(images[image]->blurred, y, feature.firstDerivative, width, o[1]);  // ∂y
            filterColumns(images[image]->curvature, y, feature.gaussian, width, o[2]);  // ∂xx
            filterColumns(images[image]->blurred, y, feature.secondDerivative, width, o[3]);  // ∂yy
        }
        for (int x = 0; x < width; ++x) {
            auto length = [&](int dx, int dy) {
                return std::sqrt(out[dx][x] * out[dx][x] + out[dy][x] * out[dy][x]);
            };
            const float edgeReference = length(0, 1), pointReference = length(2, 3);
            const float edgeTest = length(4, 5), pointTest = length(6, 7);
            float& value = error[std::size_t(y) * width + x];
            value = flip::combineFlip(
                value, flip::featureDifference(edgeReference, edgeTest, pointReference, pointTest));
        }
    }
}

}  // namespace

FlipStats poolFlip(const std::vector<float>& errors) {
    FlipStats stats;
    stats.pixels = errors.size();
    if (errors.empty()) return stats;
    // Non-negative floats order like their bit patterns: the top bits (exponent and three
    // mantissa bits) sort errors into ordered buckets, so a weighted percentile needs sorting
    // only within the one bucket where the running sum passes it.
    constexpr int kBucketShift = 20;
    constexpr std::size_t kBuckets = std::size_t(1) << (31 - kBucketShift);
    auto bucketOf = [](float error) {
        return std::min(std::size_t(std::bit_cast<std::uint32_t>(std::max(error, 0.0f)) >>
                                    kBucketShift),
                        kBuckets - 1);
    };
    std::vector<double> bucketSums(kBuckets, 0.0);
    double total = 0;
    float largest = 0;
    for (float error : errors) {
        bucketSums[bucketOf(error)] += error;
        total += error;
        largest = std::max(largest, error);
    }
    stats.mean = total / double(errors.size());
    stats.max = largest;
    // The smallest error at which the running sum, in ascending order, passes fraction · total.
    auto weightedPercentile = [&](double fraction) {
        const double threshold = fraction * total;
        double below = 0;
        std::size_t bucket = 0;
        while (bucket + 1 < kBuckets && below + bucketSums[bucket] <= threshold)
            below += bucketSums[bucket++];
        std::vector<float> inBucket;
        for (float error : errors)
            if (bucketOf(error) == bucket) inBucket.push_back(error);
        std::sort(inBucket.begin(), inBucket.end());
        for (float error : inBucket) {
            below += error;
            if (below > threshold) return double(error);
        }
        return 0.0;  // every error is 0
    };
    stats.firstWeightedQuartile = weightedPercentile(0.25);
    stats.weightedMedian = weightedPercentile(0.5);
    stats.thirdWeightedQuartile = weightedPercentile(0.75);
    return stats;
}

Result<FlipMap> computeFlip(const Image& reference, const Image& test, bool useAlpha,
                            const FlipSettings& settings, unsigned workerCount) {
    if (auto comparable = requireComparable(reference, test); !comparable)
        return comparable.error();
    const std::size_t pixelCount = reference.pixelCount();
    if (!(settings.pixelsPerDegree > 0.0) || settings.pixelsPerDegree > 1000.0)
        return Error{"pixels per degree must be in (0, 1000]"};

    FlipMap map;
    map.width = reference.width;
    map.height = reference.height;
    map.error.resize(pixelCount);
    map.pooled.resize(pixelCount);
    if (pixelCount == 0) return map;

    const OpponentPlanes referencePlanes = toOpponentPlanes(reference);
    const OpponentPlanes testPlanes = toOpponentPlanes(test);
    const Kernels kernels{flip::makeCsfKernels(settings.pixelsPerDegree),
                          flip::makeFeatureKernels(settings.pixelsPerDegree)};
    const std::size_t bands = std::size_t((map.height + kBandRows - 1) / kBandRows);
    detail::forEachChunk(bands, workerCount, [&](std::size_t band) {
        const int firstRow = int(band) * kBandRows;
        const int endRow = std::min(map.height, firstRow + kBandRows);
        colorErrorOfBand(referencePlanes, testPlanes, map.width, map.height, firstRow, endRow,
                         kernels.csf, map.error.data());
        flipOfBand(referencePlanes, testPlanes, map.width, map.height, firstRow, endRow,
                   kernels.feature, map.error.data());
    });

    std::vector<float> pooledErrors;
    pooledErrors.reserve(pixelCount);
    for (std::size_t i = 0; i < pixelCount; ++i) {
        const bool counts = !useAlpha || (isCovered(reference.rgba[4 * i + 3]) &&
                                          isCovered(test.rgba[4 * i + 3]));
        map.pooled[i] = counts ? 1 : 0;
        if (counts) pooledErrors.push_back(map.error[i]);
    }
    map.stats = poolFlip(pooledErrors);
    return map;
}

}  // namespace matevo
