#include "color/Flip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <memory>
#include <string>

#include "color/Coverage.h"
#include "color/ImageDifference.h"
#include "color/detail/FlipFormulas.h"
#include "color/detail/ScratchShelf.h"
#include "color/detail/VectorisedKernel.h"
#include "common/HugePages.h"
#include "common/ParallelFor.h"

namespace matevo {
namespace {

// A tile of work: its pixels' rows and columns plus the filter radius around them are filtered
// along x into tile-local planes, then along y. Taller tiles repeat less of the row pass;
// narrower ones keep the fourteen planes (seven per image) in the core's cache between the two
// passes (whole 2048-pixel rows were megabytes per worker).
constexpr int kTileRows = 64;
constexpr int kTileColumns = 128;

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
    for (int f = 0; f < Count; ++f) std::memcpy(out[f] + x0, &sums[f][0], sizeof sums[f]);
}

// out[f][x] = Σ_k taps[f][k] lines[k][x] for `Count` filters of one radius over the same
// 2r + 1 lines (the shifts of one padded row, or rows of a tile): each pair of mirrored lines
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
        case 1:
            filterLinesOf<1>(taps.begin(), width, lines, out.begin());
            break;
        case 2:
            filterLinesOf<2>(taps.begin(), width, lines, out.begin());
            break;
        default:
            filterLinesOf<3>(taps.begin(), width, lines, out.begin());
            break;
    }
}

// One row of a tile in YyCxCz, a line per channel, and the achromatic channel normalised to
// [0, 1] for the feature detectors; each line holds the tile's columns and `padding` more on
// both sides for the row filters, edge pixels repeated past the image's edges.
struct OpponentRow {
    int padding = 0;
    std::vector<float> achromatic, redGreen, blueYellow, lightness;
    // Where the tile's column x (0 at its first) is.
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

// Columns [firstColumn − padding, endColumn + padding) of image row y.
void convertRow(const Image& image, int y, int firstColumn, int endColumn, int padding,
                OpponentRow& row) {
    const int lineStart = firstColumn - padding, lineEnd = endColumn + padding;
    const int inside = std::max(lineStart, 0), insideEnd = std::min(lineEnd, image.width);
    row.padding = padding;
    for (auto* line : {&row.achromatic, &row.redGreen, &row.blueYellow, &row.lightness})
        line->resize(std::size_t(lineEnd - lineStart));
    const int offset = inside - lineStart;
    opponentRange(&image.rgba[4 * (std::size_t(y) * std::size_t(image.width) + inside)],
                  std::size_t(insideEnd - inside), row.achromatic.data() + offset,
                  row.redGreen.data() + offset, row.blueYellow.data() + offset,
                  row.lightness.data() + offset);
    for (auto* line : {&row.achromatic, &row.redGreen, &row.blueYellow, &row.lightness}) {
        float* values = line->data();
        std::fill(values, values + offset, values[offset]);
        const int last = insideEnd - lineStart - 1;
        std::fill(values + last + 1, values + (lineEnd - lineStart), values[last]);
    }
}

// The row pass of one tile for one plane: image rows [first, first + count) (clamped at the
// image's edges) filtered along x over the tile's columns, stored consecutively.
class RowFiltered {
public:
    // Keeps its buffer's memory from tile to tile. Rows are a cache line longer than a whole
    // number of lines: the column passes load the same column of 2r + 1 rows, which at a
    // stride of a multiple of 4 KiB (1024 pixels) all fall in one set of the L1 cache.
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
    return {halfOf(csf.achromatic),           halfOf(csf.redGreen),
            halfOf(csf.blueYellow[0]),        halfOf(csf.blueYellow[1]),
            halfOf(feature.gaussian),         halfOf(feature.firstDerivative),
            halfOf(feature.secondDerivative), float(flip::maxColorDistance())};
}

// The planes a tile's row passes fill for one image, each filtered along x.
enum Plane {
    kAchromatic,
    kRedGreen,
    kBlueYellow0,
    kBlueYellow1,  // contrast sensitivity, step 2
    kSlope,
    kCurvature,
    kBlurred,  // first, second derivative, Gaussian
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
MATEVO_VECTORISED_KERNEL void combineRow(const float* const* derivatives, int width, float* error) {
    for (int x = 0; x < width; ++x) {
        auto length = [&](int dx, int dy) {
            return std::sqrt(derivatives[dx][x] * derivatives[dx][x] +
                             derivatives[dy][x] * derivatives[dy][x]);
        };
        error[x] = flip::formulas::combine(
            error[x], flip::formulas::featureDifference(length(0, 1), length(4, 5), length(2, 3),
                                                        length(6, 7)));
    }
}

// Where one chunk of work lies in the image: rows [firstRow, endRow), columns
// [firstColumn, endColumn).
struct Tile {
    int firstRow, endRow, firstColumn, endColumn;
    int width() const { return endColumn - firstColumn; }
};

// One worker's buffers, reused from tile to tile and kept from call to call (ScratchShelf.h):
// a converted row, the row passes of both images, the line pointers of a filter and the column
// sums of one row.
struct TileScratch {
    OpponentRow opponent;
    std::array<std::array<RowFiltered, kPlaneCount>, 2> rows;  // [image][plane]
    std::vector<const float*> lines;
    std::vector<float> sums;
    FlipPooling pooling;  // of the tiles this worker computed
};

// The 2r + 1 shifts of a padded line around the tile's first column, for a filter of radius r.
const float* const* shiftsOf(const OpponentRow& row, const std::vector<float>& line, int radius,
                             std::vector<const float*>& lines) {
    lines.resize(std::size_t(2 * radius + 1));
    for (int k = -radius; k <= radius; ++k) lines[std::size_t(k + radius)] = row.at(line, k);
    return lines.data();
}

// The 2r + 1 stored rows around image row y, for a filter of radius r.
const float* const* rowsAround(const RowFiltered& plane, int y, int radius,
                               std::vector<const float*>& lines) {
    lines.resize(std::size_t(2 * radius + 1));
    for (int k = -radius; k <= radius; ++k) lines[std::size_t(k + radius)] = plane.row(y + k);
    return lines.data();
}

// The row passes of both images over the tile and `halo` more rows above and below, each
// image row converted once for all seven filters.
void rowPasses(const Image& reference, const Image& test, const Tile& tile, int halo,
               const Kernels& kernels, TileScratch& scratch) {
    const Image* images[2] = {&reference, &test};
    const int width = tile.width();
    const int csfRadius = kernels.achromatic.radius(), featureRadius = kernels.gaussian.radius();
    const OpponentRow& row = scratch.opponent;
    for (std::size_t image = 0; image < 2; ++image) {
        auto& planes = scratch.rows[image];
        for (RowFiltered& plane : planes)
            plane.resize(width, tile.firstRow - halo, tile.endRow - tile.firstRow + 2 * halo);
        for (int y = tile.firstRow - halo; y < tile.endRow + halo; ++y) {
            convertRow(*images[image], std::clamp(y, 0, reference.height - 1), tile.firstColumn,
                       tile.endColumn, halo, scratch.opponent);
            filterLines({&kernels.achromatic}, width,
                        shiftsOf(row, row.achromatic, csfRadius, scratch.lines),
                        {planes[kAchromatic].row(y)});
            filterLines({&kernels.redGreen}, width,
                        shiftsOf(row, row.redGreen, csfRadius, scratch.lines),
                        {planes[kRedGreen].row(y)});
            filterLines({&kernels.blueYellow0, &kernels.blueYellow1}, width,
                        shiftsOf(row, row.blueYellow, csfRadius, scratch.lines),
                        {planes[kBlueYellow0].row(y), planes[kBlueYellow1].row(y)});
            filterLines(
                {&kernels.firstDerivative, &kernels.secondDerivative, &kernels.gaussian}, width,
                shiftsOf(row, row.lightness, featureRadius, scratch.lines),
                {planes[kSlope].row(y), planes[kCurvature].row(y), planes[kBlurred].row(y)});
        }
    }
}

// ꟻLIP of one tile: the row passes, then row by row the column passes, the colour error
// (step 3), the feature error (step 4) and their combination (step 5).
void flipOfTile(const Image& reference, const Image& test, const Tile& tile, const Kernels& kernels,
                TileScratch& scratch, float* error) {
    const int width = tile.width();
    const int csfRadius = kernels.achromatic.radius(), featureRadius = kernels.gaussian.radius();
    // Columns, clamped at the image's edges: a tile's stored rows already repeat them.
    rowPasses(reference, test, tile, std::max(csfRadius, featureRadius), kernels, scratch);
    constexpr int kOutputs = 16;  // per image: four colour and four derivative sums
    scratch.sums.resize(std::size_t(width) * kOutputs);
    float* out[kOutputs];
    for (int c = 0; c < kOutputs; ++c) out[c] = &scratch.sums[std::size_t(c) * width];
    float* const* colorSums = out;           // [4 image + channel]
    float* const* derivativeSums = out + 8;  // [4 image + ∂x, ∂y, ∂xx, ∂yy]
    const std::pair<Plane, const Taps*> csf[] = {{kAchromatic, &kernels.achromatic},
                                                 {kRedGreen, &kernels.redGreen},
                                                 {kBlueYellow0, &kernels.blueYellow0},
                                                 {kBlueYellow1, &kernels.blueYellow1}};
    for (int y = tile.firstRow; y < tile.endRow; ++y) {
        for (std::size_t image = 0; image < 2; ++image) {
            const auto& planes = scratch.rows[image];
            auto around = [&](Plane plane, int radius) {
                return rowsAround(planes[plane], y, radius, scratch.lines);
            };
            float* const* color = colorSums + 4 * image;
            float* const* derivative = derivativeSums + 4 * image;
            for (int c = 0; c < 4; ++c)
                filterLines({csf[c].second}, width, around(csf[c].first, csfRadius), {color[c]});
            filterLines({&kernels.gaussian}, width, around(kSlope, featureRadius), {derivative[0]});
            filterLines({&kernels.firstDerivative, &kernels.secondDerivative}, width,
                        around(kBlurred, featureRadius), {derivative[1], derivative[3]});
            filterLines({&kernels.gaussian}, width, around(kCurvature, featureRadius),
                        {derivative[2]});
        }
        float* rowError = error + std::size_t(y) * std::size_t(reference.width) + tile.firstColumn;
        colorErrorRow(colorSums, width, kernels.maxColorDistance, rowError);
        combineRow(derivativeSums, width, rowError);
    }
}

// Which of the tile's pixels count in the statistics, and their errors added to the pooling.
void poolTile(const Image& reference, const Image& test, bool useAlpha, const Tile& tile,
              ErrorMap& map, FlipPooling& pooling) {
    for (int y = tile.firstRow; y < tile.endRow; ++y) {
        const std::size_t rowStart = std::size_t(y) * std::size_t(map.width);
        for (std::size_t i = rowStart + std::size_t(tile.firstColumn);
             i < rowStart + std::size_t(tile.endColumn); ++i) {
            const bool counts = !useAlpha || (isCovered(reference.rgba[4 * i + 3]) &&
                                              isCovered(test.rgba[4 * i + 3]));
            map.covered[i] = counts ? 1 : 0;
            pooling.add(map.values[i], counts);
        }
    }
}

}  // namespace

Result<ErrorMap> computeFlip(const Image& reference, const Image& test, bool useAlpha,
                             const FlipSettings& settings, unsigned workerCount) {
    if (auto comparable = requireComparable(reference, test); !comparable)
        return comparable.error();
    const std::size_t pixelCount = reference.pixelCount();
    if (!(settings.pixelsPerDegree > 0.0) || settings.pixelsPerDegree > 1000.0)
        return badInput("pixels per degree must be in (0, 1000]");

    ErrorMap map;
    map.metric = ImageMetric::Flip;
    map.width = reference.width;
    map.height = reference.height;
    resizeOnHugePages(map.values, pixelCount);
    resizeOnHugePages(map.covered, pixelCount);
    if (pixelCount == 0) return map;

    const Kernels kernels = makeKernels(settings.pixelsPerDegree);
    const int tileRows = (map.height + kTileRows - 1) / kTileRows;
    const int tileColumns = (map.width + kTileColumns - 1) / kTileColumns;
    static detail::ScratchShelf<TileScratch> shelf;
    auto scratches = parallelForChunksWithScratch(
        tileRows * tileColumns,
        [] {
            auto scratch = shelf.take();
            scratch->pooling.clear();
            return scratch;
        },
        [&](detail::ScratchShelf<TileScratch>::Shelved& scratch, int chunk) {
            const int row = chunk / tileColumns, column = chunk % tileColumns;
            const Tile tile{row * kTileRows, std::min(map.height, (row + 1) * kTileRows),
                            column * kTileColumns,
                            std::min(map.width, (column + 1) * kTileColumns)};
            flipOfTile(reference, test, tile, kernels, *scratch, map.values.data());
            poolTile(reference, test, useAlpha, tile, map, scratch->pooling);
        },
        workerCount);
    FlipPooling& pooling = scratches.front()->pooling;
    for (std::size_t i = 1; i < scratches.size(); ++i) pooling.merge(scratches[i]->pooling);
    map.stats = pooling.finish(map.values, map.covered, workerCount);
    return map;
}

}  // namespace matevo
