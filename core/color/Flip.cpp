#include "color/Flip.h"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <memory>
#include <cmath>
#include <cstring>
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

// A filter's taps right of and at its centre, and whether its left half mirrors them (even)
// or their negatives (odd): our filters are Gaussians and their derivatives, so each mirrored
// pair of lines is added (or subtracted) before one multiply, which halves the work.
struct Taps {
    std::vector<float> halfFromCentre;  // taps[r], taps[r + 1], ..., taps[2r]
    bool odd = false;
    int radius() const { return int(halfFromCentre.size()) - 1; }
};

Taps halfOf(const std::vector<float>& values) {
    const std::size_t centre = values.size() / 2;
    return {std::vector<float>(values.begin() + std::ptrdiff_t(centre), values.end()),
            values[centre] == 0.0f && values.front() == -values.back()};
}

// Sixteen pixels as one value: GCC and Clang compile its arithmetic to the widest registers
// the kernel's clone targets (one AVX-512, two AVX2 or four SSE registers).
constexpr int kVectorWidth = 16;
typedef float FloatVector __attribute__((vector_size(kVectorWidth * sizeof(float))));

// Filters `Vectors` × 16 pixels from x0 on (see filterLinesOf), their sums kept in registers
// across all taps: each tap costs two loads and no store, and the vectors are independent
// chains of additions, so one waits less on the latency of another.
template <int Count, int Vectors>
[[gnu::always_inline]] inline void filterBlock(const Taps* const* taps, const float* const* lines,
                                               float* const* out, int x0) {
    const int r = taps[0]->radius();
    FloatVector sums[Count][Vectors];
    for (int v = 0; v < Vectors; ++v) {
        FloatVector centre;
        std::memcpy(&centre, lines[r] + x0 + v * kVectorWidth, sizeof centre);
        for (int f = 0; f < Count; ++f) sums[f][v] = taps[f]->halfFromCentre[0] * centre;
    }
    for (int k = r; k >= 1; --k) {
        for (int v = 0; v < Vectors; ++v) {
            FloatVector low, high;
            std::memcpy(&low, lines[r - k] + x0 + v * kVectorWidth, sizeof low);
            std::memcpy(&high, lines[r + k] + x0 + v * kVectorWidth, sizeof high);
            const FloatVector pairSum = low + high, pairDifference = high - low;
            for (int f = 0; f < Count; ++f)
                sums[f][v] += taps[f]->halfFromCentre[std::size_t(k)] *
                              (taps[f]->odd ? pairDifference : pairSum);
        }
    }
    for (int f = 0; f < Count; ++f)
        std::memcpy(out[f] + x0, &sums[f][0], sizeof sums[f]);
}

// out[f][x] = Σ_k taps[f][k] lines[k][x] for `Count` filters of one radius over the same
// 2r + 1 lines (the shifts of one padded row, or rows of a band): each pair of mirrored lines
// is loaded, added and subtracted once for all the filters. Every pixel is summed in the same
// order (the centre, then the pairs from the outermost in), whichever path below takes it.
template <int Count>
[[gnu::always_inline]] inline void filterLinesOf(const Taps* const* taps, int width,
                                                 const float* const* lines, float* const* out) {
    constexpr int kWide = 4;  // vectors per block where the line is long enough
    int x0 = 0;
    for (; x0 + kWide * kVectorWidth <= width; x0 += kWide * kVectorWidth)
        filterBlock<Count, kWide>(taps, lines, out, x0);
    for (; x0 + kVectorWidth <= width; x0 += kVectorWidth)
        filterBlock<Count, 1>(taps, lines, out, x0);
    if (x0 == width) return;
    if (width >= kVectorWidth) {
        // One last vector that ends at the line's end, overlapping its predecessor: it writes
        // the same values again.
        filterBlock<Count, 1>(taps, lines, out, width - kVectorWidth);
        return;
    }
    const int r = taps[0]->radius();
    for (int x = 0; x < width; ++x)
        for (int f = 0; f < Count; ++f) {
            const std::vector<float>& half = taps[f]->halfFromCentre;
            float sum = half[0] * lines[r][x];
            for (int k = r; k >= 1; --k) {
                const float low = lines[r - k][x], high = lines[r + k][x];
                sum += half[std::size_t(k)] * (taps[f]->odd ? high - low : low + high);
            }
            out[f][x] = sum;
        }
}

MATEVO_VECTORISED_KERNEL void filterLines(std::initializer_list<const Taps*> taps, int width,
                                          const float* const* lines,
                                          std::initializer_list<float*> out) {
    switch (taps.size()) {
    case 1: filterLinesOf<1>(taps.begin(), width, lines, out.begin()); break;
    case 2: filterLinesOf<2>(taps.begin(), width, lines, out.begin()); break;
    default: filterLinesOf<3>(taps.begin(), width, lines, out.begin()); break;
    }
}

// One image row in YyCxCz, a line per channel, and the achromatic channel normalised to [0, 1]
// for the feature detectors, each line with `padding` copies of its edge pixels on both sides
// for the row filters. Rows are converted as a band's row passes need them rather than kept
// as whole-image planes, which at 2048² were 128 MB written and read again.
struct OpponentRow {
    int padding = 0;
    std::vector<float> achromatic, redGreen, blueYellow, lightness;
    const float* at(const std::vector<float>& line, int x) const {
        return line.data() + padding + x;
    }
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

void convertRow(const Image& image, int y, int padding, OpponentRow& row) {
    const int width = image.width;
    row.padding = padding;
    for (auto* line : {&row.achromatic, &row.redGreen, &row.blueYellow, &row.lightness})
        line->resize(std::size_t(width + 2 * padding));
    opponentRange(&image.rgba[4 * std::size_t(y) * std::size_t(width)], std::size_t(width),
                  row.achromatic.data() + padding, row.redGreen.data() + padding,
                  row.blueYellow.data() + padding, row.lightness.data() + padding);
    for (auto* line : {&row.achromatic, &row.redGreen, &row.blueYellow, &row.lightness}) {
        float* values = line->data();
        std::fill(values, values + padding, values[padding]);
        std::fill(values + padding + width, values + width + 2 * padding,
                  values[padding + width - 1]);
    }
}

// The row pass of one band for one plane: image rows [first, first + count) (clamped at the
// image's edges) filtered along x, stored consecutively.
class RowFiltered {
public:
    // Keeps its buffer's memory from band to band. Rows are a cache line longer than a whole
    // number of lines: the column passes load the same column of 2r + 1 rows, which at a
    // stride of a multiple of 4 KiB (a 2048-pixel row) all fall in one set of the L1 cache.
    // Not zeroed: the row passes write every value the column passes read.
    void resize(int width, int first, int count) {
        stride_ = (std::size_t(width) + 15) / 16 * 16 + 16;
        first_ = first;
        const std::size_t size = stride_ * std::size_t(count);
        if (size > capacity_) {
            rows_ = std::make_unique_for_overwrite<float[]>(size);
            capacity_ = size;
        }
    }
    // The stored row for image row y (first_ ≤ y < first_ + count).
    const float* row(int y) const { return &rows_[std::size_t(y - first_) * stride_]; }
    float* row(int y) { return &rows_[std::size_t(y - first_) * stride_]; }

private:
    std::size_t stride_ = 0, capacity_ = 0;
    int first_ = 0;
    std::unique_ptr<float[]> rows_;
};

struct Kernels {
    Taps achromatic, redGreen, blueYellow0, blueYellow1;  // contrast sensitivity
    Taps gaussian, firstDerivative, secondDerivative;     // feature detectors
    float maxColorDistance = 0;
};

Kernels makeKernels(double pixelsPerDegree) {
    const flip::CsfKernels csf = flip::makeCsfKernels(pixelsPerDegree);
    const flip::FeatureKernels feature = flip::makeFeatureKernels(pixelsPerDegree);
    return {halfOf(csf.achromatic),      halfOf(csf.redGreen),
            halfOf(csf.blueYellow[0]),   halfOf(csf.blueYellow[1]),
            halfOf(feature.gaussian),    halfOf(feature.firstDerivative),
            halfOf(feature.secondDerivative), float(flip::maxColorDistance())};
}

// The planes a band's row passes fill for one image, each filtered along x.
enum Plane {
    kAchromatic, kRedGreen, kBlueYellow0, kBlueYellow1,  // contrast sensitivity, step 2
    kSlope, kCurvature, kBlurred,                        // first, second derivative, Gaussian
    kPlaneCount
};

// Step 3 along one row from the column-filtered opponent planes of both images (the
// blue-yellow channel is the sum of its two terms).
MATEVO_VECTORISED_KERNEL void colorErrorRow(const float* const* filtered, int width,
                                            float maxColorDistance, float* colorError) {
    for (int x = 0; x < width; ++x)
        colorError[x] = flip::formulas::colorDifference(
            {filtered[0][x], filtered[1][x], filtered[2][x] + filtered[3][x]},
            {filtered[4][x], filtered[5][x], filtered[6][x] + filtered[7][x]}, maxColorDistance);
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

// One worker's buffers, reused from band to band (a band's are megabytes, which the allocator
// would map and unmap each time): a converted row, the row passes of both images, the line
// pointers of a filter and the column sums of one row.
struct BandScratch {
    OpponentRow opponent;
    std::array<std::array<RowFiltered, kPlaneCount>, 2> rows;  // [image][plane]
    std::vector<const float*> lines;
    std::vector<float> sums;
    FlipPooling pooling;  // of the bands this worker computed
};

// The 2r + 1 shifts of a padded line around x = 0, for a filter of radius r.
const float* const* shiftsOf(const OpponentRow& row, const std::vector<float>& line, int radius,
                             std::vector<const float*>& lines) {
    lines.resize(std::size_t(2 * radius + 1));
    for (int k = -radius; k <= radius; ++k) lines[std::size_t(k + radius)] = row.at(line, k);
    return lines.data();
}

// The 2r + 1 stored rows around image row y from column x on, for a filter of radius r.
const float* const* rowsAround(const RowFiltered& plane, int y, int x, int radius,
                               std::vector<const float*>& lines) {
    lines.resize(std::size_t(2 * radius + 1));
    for (int k = -radius; k <= radius; ++k) lines[std::size_t(k + radius)] = plane.row(y + k) + x;
    return lines.data();
}

// The row passes of both images over the band's rows and `halo` more above and below, each
// image row converted once for all seven filters.
void rowPasses(const Image& reference, const Image& test, int firstRow, int endRow, int halo,
               const Kernels& kernels, BandScratch& scratch) {
    const Image* images[2] = {&reference, &test};
    const int width = reference.width, height = reference.height;
    const int csfRadius = kernels.achromatic.radius(), featureRadius = kernels.gaussian.radius();
    const OpponentRow& row = scratch.opponent;
    for (std::size_t image = 0; image < 2; ++image) {
        auto& planes = scratch.rows[image];
        for (RowFiltered& plane : planes)
            plane.resize(width, firstRow - halo, endRow - firstRow + 2 * halo);
        for (int y = firstRow - halo; y < endRow + halo; ++y) {
            convertRow(*images[image], std::clamp(y, 0, height - 1), halo, scratch.opponent);
            filterLines({&kernels.achromatic}, width,
                        shiftsOf(row, row.achromatic, csfRadius, scratch.lines),
                        {planes[kAchromatic].row(y)});
            filterLines({&kernels.redGreen}, width,
                        shiftsOf(row, row.redGreen, csfRadius, scratch.lines),
                        {planes[kRedGreen].row(y)});
            filterLines({&kernels.blueYellow0, &kernels.blueYellow1}, width,
                        shiftsOf(row, row.blueYellow, csfRadius, scratch.lines),
                        {planes[kBlueYellow0].row(y), planes[kBlueYellow1].row(y)});
            filterLines({&kernels.firstDerivative, &kernels.secondDerivative, &kernels.gaussian},
                        width, shiftsOf(row, row.lightness, featureRadius, scratch.lines),
                        {planes[kSlope].row(y), planes[kCurvature].row(y), planes[kBlurred].row(y)});
        }
    }
}

// Columns of a band filtered together: the column passes of all fourteen planes read 2r + 1
// stored rows each, which for a strip this wide stay in the core's cache from one output row
// to the next (over a 2048-pixel row they did not).
constexpr int kStripWidth = 256;

// ꟻLIP of one band's rows: the row passes, then strip by strip and row by row the column
// passes, the colour error (step 3), the feature error (step 4) and their combination (step 5).
void flipOfBand(const Image& reference, const Image& test, int firstRow, int endRow,
                const Kernels& kernels, BandScratch& scratch, float* error) {
    const int width = reference.width;
    const int csfRadius = kernels.achromatic.radius(), featureRadius = kernels.gaussian.radius();
    // Columns, clamped at the image's edges: a band's stored rows already repeat them.
    rowPasses(reference, test, firstRow, endRow, std::max(csfRadius, featureRadius), kernels,
              scratch);
    constexpr int kOutputs = 16;  // per image: four colour and four derivative sums
    scratch.sums.resize(std::size_t(kStripWidth) * kOutputs);
    float* out[kOutputs];
    for (int c = 0; c < kOutputs; ++c) out[c] = &scratch.sums[std::size_t(c) * kStripWidth];
    float* const* colorSums = out;           // [4 image + channel]
    float* const* derivativeSums = out + 8;  // [4 image + ∂x, ∂y, ∂xx, ∂yy]
    const std::pair<Plane, const Taps*> csf[] = {{kAchromatic, &kernels.achromatic},
                                                 {kRedGreen, &kernels.redGreen},
                                                 {kBlueYellow0, &kernels.blueYellow0},
                                                 {kBlueYellow1, &kernels.blueYellow1}};
    for (int x0 = 0; x0 < width; x0 += kStripWidth) {
        const int stripWidth = std::min(kStripWidth, width - x0);
        for (int y = firstRow; y < endRow; ++y) {
            for (std::size_t image = 0; image < 2; ++image) {
                const auto& planes = scratch.rows[image];
                auto around = [&](Plane plane, int radius) {
                    return rowsAround(planes[plane], y, x0, radius, scratch.lines);
                };
                float* const* color = colorSums + 4 * image;
                float* const* derivative = derivativeSums + 4 * image;
                for (int c = 0; c < 4; ++c)
                    filterLines({csf[c].second}, stripWidth, around(csf[c].first, csfRadius),
                                {color[c]});
                filterLines({&kernels.gaussian}, stripWidth, around(kSlope, featureRadius),
                            {derivative[0]});
                filterLines({&kernels.firstDerivative, &kernels.secondDerivative}, stripWidth,
                            around(kBlurred, featureRadius), {derivative[1], derivative[3]});
                filterLines({&kernels.gaussian}, stripWidth, around(kCurvature, featureRadius),
                            {derivative[2]});
            }
            float* stripError = error + std::size_t(y) * width + x0;
            colorErrorRow(colorSums, stripWidth, kernels.maxColorDistance, stripError);
            combineRow(derivativeSums, stripWidth, stripError);
        }
    }
}

// Which of the rows' pixels count in the statistics, and their errors added to the pooling.
void poolRows(const Image& reference, const Image& test, bool useAlpha, int firstRow, int endRow,
              FlipMap& map, FlipPooling& pooling) {
    const std::size_t end = std::size_t(endRow) * std::size_t(map.width);
    for (std::size_t i = std::size_t(firstRow) * std::size_t(map.width); i < end; ++i) {
        const bool counts = !useAlpha || (isCovered(reference.rgba[4 * i + 3]) &&
                                          isCovered(test.rgba[4 * i + 3]));
        map.pooled[i] = counts ? 1 : 0;
        pooling.add(map.error[i], counts);
    }
}

}  // namespace

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
    const auto scratches = detail::forEachChunkWithScratch(
        bands, workerCount, [] { return BandScratch{}; },
        [&](BandScratch& scratch, std::size_t band) {
            const int firstRow = int(band) * kBandRows;
            const int endRow = std::min(map.height, firstRow + kBandRows);
            flipOfBand(reference, test, firstRow, endRow, kernels, scratch, map.error.data());
            poolRows(reference, test, useAlpha, firstRow, endRow, map, scratch.pooling);
        });
    FlipPooling pooling;
    for (const BandScratch& scratch : scratches) pooling.merge(scratch.pooling);
    map.stats = pooling.finish(map.error, map.pooled);
    return map;
}

}  // namespace matevo
