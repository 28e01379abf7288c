#include "color/Flip.h"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <bit>
#include <cmath>
#include <string>

#include "color/Coverage.h"
#include "color/ImageDifference.h"
#include "color/detail/FlipFormulas.h"
#include "color/detail/ForEachChunk.h"
#include "color/detail/VectorisedKernel.h"
#include "common/HugePages.h"

namespace matevo {
namespace {

// Rows per band of work. A band filters the rows it needs along x (its own plus the filter
// radius above and below) into band-local buffers, then along y: more rows per band repeat
// less of the row pass, fewer keep the buffers in cache.
constexpr int kBandRows = 64;

// One image row in YyCxCz, a line per channel, and the achromatic channel normalised to [0, 1]
// for the feature detectors. Rows are converted as a band's row passes need them rather than
// kept as whole-image planes, which at 2048² were 128 MB written and read again.
struct OpponentRow {
    std::vector<float> achromatic, redGreen, blueYellow, lightness;
};

MATEVO_VECTORISED_KERNEL void opponentRange(const float* rgba, std::size_t count, float* achromatic,
                                            float* redGreen, float* blueYellow, float* lightness) {
    for (std::size_t i = 0; i < count; ++i) {
        const float* pixel = rgba + 4 * i;
        const float alpha = std::clamp(pixel[3], 0.0f, 1.0f);  // over black
        const flip::Ycxcz color =
            flip::formulas::ycxczOf(pixel[0] * alpha, pixel[1] * alpha, pixel[2] * alpha);
        achromatic[i] = color.y;
        redGreen[i] = color.cx;
        blueYellow[i] = color.cz;
        lightness[i] = (color.y + 16.0f) * (1.0f / 116.0f);
    }
}

void convertRow(const Image& image, int y, OpponentRow& row) {
    const std::size_t width = std::size_t(image.width);
    for (auto* line : {&row.achromatic, &row.redGreen, &row.blueYellow, &row.lightness})
        line->resize(width);
    opponentRange(&image.rgba[4 * std::size_t(y) * width], width, row.achromatic.data(),
                  row.redGreen.data(), row.blueYellow.data(), row.lightness.data());
}

// A filter's taps and their mirror symmetry. Our filters are Gaussians and their derivatives:
// even (taps[r + k] = taps[r − k]) or odd (= −taps[r − k]), so each mirrored pair is added
// (or subtracted) before one multiply, which halves the work.
struct Taps {
    std::vector<float> values;
    int radius = 0;
    enum class Symmetry { Even, Odd, None } symmetry = Symmetry::None;
};

Taps withSymmetry(const std::vector<float>& values) {
    Taps taps{values, int(values.size() / 2), Taps::Symmetry::Even};
    bool even = true, odd = values[std::size_t(taps.radius)] == 0.0f;
    for (std::size_t k = 0; k < values.size(); ++k) {
        even &= values[k] == values[values.size() - 1 - k];
        odd &= values[k] == -values[values.size() - 1 - k];
    }
    taps.symmetry = even ? Taps::Symmetry::Even : odd ? Taps::Symmetry::Odd : Taps::Symmetry::None;
    return taps;
}

// out[x] += Σ_k taps[k] lines[k][x] over the 2r + 1 lines around x: shifts of one padded row
// (filtering along x) or rows of a band (along y).
MATEVO_VECTORISED_KERNEL void accumulateFiltered(const Taps& taps, int width,
                                                 const float* const* lines, float* out) {
    const float* values = taps.values.data();
    const int r = taps.radius;
    if (taps.symmetry == Taps::Symmetry::None) {
        for (int k = 0; k <= 2 * r; ++k)
            for (int x = 0; x < width; ++x) out[x] += values[k] * lines[k][x];
        return;
    }
    const float* centre = lines[r];
    for (int x = 0; x < width; ++x) out[x] += values[r] * centre[x];
    // Mirrored pairs: added for an even filter, subtracted for an odd one.
    for (int k = 0; k < r; ++k) {
        const float* low = lines[k];
        const float* high = lines[2 * r - k];
        const float tap = values[k];
        if (taps.symmetry == Taps::Symmetry::Even)
            for (int x = 0; x < width; ++x) out[x] += tap * (low[x] + high[x]);
        else
            for (int x = 0; x < width; ++x) out[x] += tap * (low[x] - high[x]);
    }
}

// Scratch space of one band's worker: a padded row and the line pointers.
struct FilterScratch {
    std::vector<float> padded;
    std::vector<const float*> lines;
};

// out = the row `in` filtered along x, edge pixels repeated.
void filterRow(const float* in, int width, const Taps& taps, FilterScratch& scratch, float* out) {
    const int radius = taps.radius;
    scratch.padded.resize(std::size_t(width + 2 * radius));
    float* padded = scratch.padded.data();
    std::fill(padded, padded + radius, in[0]);
    std::copy(in, in + width, padded + radius);
    std::fill(padded + radius + width, padded + width + 2 * radius, in[width - 1]);
    scratch.lines.resize(std::size_t(2 * radius + 1));
    for (int k = 0; k <= 2 * radius; ++k) scratch.lines[std::size_t(k)] = scratch.padded.data() + k;
    std::fill(out, out + width, 0.0f);
    accumulateFiltered(taps, width, scratch.lines.data(), out);
}

// The row pass of one band for one plane: image rows [first, first + count) (clamped at the
// image's edges) filtered along x, stored consecutively.
class RowFiltered {
public:
    // Keeps its buffer's memory from band to band.
    void resize(int width, int first, int count) {
        width_ = width;
        first_ = first;
        rows_.resize(std::size_t(width) * std::size_t(count));
    }
    // The stored row for image row y (first_ ≤ y < first_ + count).
    const float* row(int y) const { return &rows_[std::size_t(y - first_) * width_]; }
    float* row(int y) { return &rows_[std::size_t(y - first_) * width_]; }

private:
    int width_ = 0, first_ = 0;
    std::vector<float> rows_;
};

// out[x] += Σ_k taps[k] rows.row(y + k − radius)[x].
void filterColumns(const RowFiltered& rows, int y, const Taps& taps, int width,
                   FilterScratch& scratch, float* out) {
    scratch.lines.resize(taps.values.size());
    for (int k = 0; k <= 2 * taps.radius; ++k)
        scratch.lines[std::size_t(k)] = rows.row(y + k - taps.radius);
    accumulateFiltered(taps, width, scratch.lines.data(), out);
}

struct Kernels {
    Taps achromatic, redGreen, blueYellow0, blueYellow1;  // contrast sensitivity
    Taps gaussian, firstDerivative, secondDerivative;     // feature detectors
    float maxColorDistance = 0;
};

Kernels makeKernels(double pixelsPerDegree) {
    const flip::CsfKernels csf = flip::makeCsfKernels(pixelsPerDegree);
    const flip::FeatureKernels feature = flip::makeFeatureKernels(pixelsPerDegree);
    return {withSymmetry(csf.achromatic),       withSymmetry(csf.redGreen),
            withSymmetry(csf.blueYellow[0]),    withSymmetry(csf.blueYellow[1]),
            withSymmetry(feature.gaussian),     withSymmetry(feature.firstDerivative),
            withSymmetry(feature.secondDerivative), float(flip::maxColorDistance())};
}

// Step 3 along one row from the filtered opponent channels of both images.
MATEVO_VECTORISED_KERNEL void colorErrorRow(const float* const* filtered, int width,
                                            float maxColorDistance, float* colorError) {
    for (int x = 0; x < width; ++x)
        colorError[x] = flip::formulas::colorDifference(
            {filtered[0][x], filtered[1][x], filtered[2][x]},
            {filtered[3][x], filtered[4][x], filtered[5][x]}, maxColorDistance);
}

// Steps 4 and 5 along one row from both images' ∂x, ∂y, ∂xx, ∂yy; error holds the colour error
// and receives ꟻLIP.
MATEVO_VECTORISED_KERNEL void combineRow(const float* const* derivatives, int width,
                                         float* error) {
    for (int x = 0; x < width; ++x) {
        auto length = [&](int dx, int dy) {
            return std::sqrt(derivatives[dx][x] * derivatives[dx][x] +
                             derivatives[dy][x] * derivatives[dy][x]);
        };
        error[x] = flip::formulas::combine(
            error[x], flip::formulas::featureDifference(length(0, 1), length(4, 5),
                                                        length(2, 3), length(6, 7)));
    }
}

// One worker's buffers, reused from band to band (a band's are hundreds of kilobytes, which
// the allocator would map and unmap each time): the row passes of both images and the column
// sums of one row.
struct BandScratch {
    FilterScratch filter;
    OpponentRow opponent;
    std::array<std::array<RowFiltered, 4>, 2> rows;  // [image][plane]
    std::vector<float> sums;
};

// Which line of a converted row a row pass filters, with which taps.
struct PlaneFilter {
    std::vector<float> OpponentRow::*line;
    const Taps* taps;
};

// The row passes of both images (rows[image][i] through filters[i]) over the band's rows and
// `radius` more above and below, each image row converted once for all the filters.
void rowPasses(const Image& reference, const Image& test,
               std::initializer_list<PlaneFilter> filters, int firstRow, int endRow, int radius,
               BandScratch& scratch) {
    const Image* images[2] = {&reference, &test};
    const int width = reference.width, height = reference.height;
    for (std::size_t image = 0; image < 2; ++image) {
        for (std::size_t i = 0; i < filters.size(); ++i)
            scratch.rows[image][i].resize(width, firstRow - radius,
                                          endRow - firstRow + 2 * radius);
        for (int y = firstRow - radius; y < endRow + radius; ++y) {
            convertRow(*images[image], std::clamp(y, 0, height - 1), scratch.opponent);
            std::size_t i = 0;
            for (const PlaneFilter& filter : filters)
                filterRow((scratch.opponent.*filter.line).data(), width, *filter.taps,
                          scratch.filter, scratch.rows[image][i++].row(y));
        }
    }
}

// The colour error (step 3) of one band's rows.
void colorErrorOfBand(const Image& reference, const Image& test, int firstRow, int endRow,
                      const Kernels& kernels, BandScratch& scratch, float* colorError) {
    const int width = reference.width;
    rowPasses(reference, test,
              {{&OpponentRow::achromatic, &kernels.achromatic},
               {&OpponentRow::redGreen, &kernels.redGreen},
               {&OpponentRow::blueYellow, &kernels.blueYellow0},
               {&OpponentRow::blueYellow, &kernels.blueYellow1}},
              firstRow, endRow, kernels.achromatic.radius, scratch);
    // Columns, clamped at the image's edges: a band's stored rows already repeat them.
    scratch.sums.resize(std::size_t(width) * 6);
    float* out[6];
    for (int c = 0; c < 6; ++c) out[c] = &scratch.sums[std::size_t(c) * width];
    for (int y = firstRow; y < endRow; ++y) {
        std::fill(scratch.sums.begin(), scratch.sums.end(), 0.0f);
        for (std::size_t image = 0; image < 2; ++image) {
            const auto& rows = scratch.rows[image];
            float* const* o = out + 3 * image;
            filterColumns(rows[0], y, kernels.achromatic, width, scratch.filter, o[0]);
            filterColumns(rows[1], y, kernels.redGreen, width, scratch.filter, o[1]);
            filterColumns(rows[2], y, kernels.blueYellow0, width, scratch.filter, o[2]);
            filterColumns(rows[3], y, kernels.blueYellow1, width, scratch.filter, o[2]);
        }
        colorErrorRow(out, width, kernels.maxColorDistance, colorError + std::size_t(y) * width);
    }
}

// The feature error (step 4) of one band's rows, combined with its colour error (step 5).
void flipOfBand(const Image& reference, const Image& test, int firstRow, int endRow,
                const Kernels& kernels, BandScratch& scratch, float* error) {
    const int width = reference.width;
    // Along x: the first and second derivative and the Gaussian of the normalised achromatic.
    rowPasses(reference, test,
              {{&OpponentRow::lightness, &kernels.firstDerivative},
               {&OpponentRow::lightness, &kernels.secondDerivative},
               {&OpponentRow::lightness, &kernels.gaussian}},
              firstRow, endRow, kernels.gaussian.radius, scratch);
    scratch.sums.resize(std::size_t(width) * 8);
    float* out[8];
    for (int c = 0; c < 8; ++c) out[c] = &scratch.sums[std::size_t(c) * width];
    for (int y = firstRow; y < endRow; ++y) {
        std::fill(scratch.sums.begin(), scratch.sums.end(), 0.0f);
        for (std::size_t image = 0; image < 2; ++image) {
            const auto& rows = scratch.rows[image];
            const RowFiltered &slope = rows[0], &curvature = rows[1], &blurred = rows[2];
            float* const* o = out + 4 * image;
            filterColumns(slope, y, kernels.gaussian, width, scratch.filter, o[0]);           // ∂x
            filterColumns(blurred, y, kernels.firstDerivative, width, scratch.filter, o[1]);  // ∂y
            filterColumns(curvature, y, kernels.gaussian, width, scratch.filter, o[2]);       // ∂xx
            filterColumns(blurred, y, kernels.secondDerivative, width, scratch.filter, o[3]); // ∂yy
        }
        combineRow(out, width, error + std::size_t(y) * width);
    }
}

}  // namespace

FlipStats poolFlip(const std::vector<float>& errors) {
    FlipStats stats;
    stats.pixels = errors.size();
    if (errors.empty()) return stats;
    // Non-negative floats order like their bit patterns: the top bits (exponent and seven
    // mantissa bits) sort errors into ordered buckets, so a weighted percentile needs sorting
    // only within the one (small) bucket where the running sum passes it.
    constexpr int kBucketShift = 16;
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
        while (bucket + 1 < kBuckets && below + bucketSums[bucket] <= threshold)
            below += bucketSums[bucket++];
        bucketOfQuartile[q] = bucket;
        belowBucket[q] = below;
    }
    std::array<std::vector<float>, 3> inBucket;
    for (float error : errors) {
        const std::size_t errorBucket = bucketOf(error);
        for (std::size_t q = 0; q < kFractions.size(); ++q)
            if (errorBucket == bucketOfQuartile[q]) inBucket[q].push_back(error);
    }
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
    resizeOnHugePages(map.error, pixelCount);
    resizeOnHugePages(map.pooled, pixelCount);
    if (pixelCount == 0) return map;

    const Kernels kernels = makeKernels(settings.pixelsPerDegree);
    const std::size_t bands = std::size_t((map.height + kBandRows - 1) / kBandRows);
    detail::forEachChunkWithScratch(
        bands, workerCount, [] { return BandScratch{}; },
        [&](BandScratch& scratch, std::size_t band) {
            const int firstRow = int(band) * kBandRows;
            const int endRow = std::min(map.height, firstRow + kBandRows);
            colorErrorOfBand(reference, test, firstRow, endRow, kernels, scratch,
                             map.error.data());
            flipOfBand(reference, test, firstRow, endRow, kernels, scratch, map.error.data());
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
