#include "color/ImageDifference.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <thread>

#include "color/detail/ColorFormulas.h"
#include "color/detail/FastFloatMath.h"

namespace matevo {
namespace {

// Fixed chunk size: the partial sums, and so the mean, never depend on the thread count.
constexpr std::size_t kChunkPixels = 16384;
constexpr float kCoverageThreshold = 0.5f;

struct ChunkSummary {
    double sum = 0;
    float max = 0;
    std::size_t pixels = 0;
};

// Float math through the shared formulas: flattened, this loop has no calls and no branches, so
// the compiler vectorises it.
[[gnu::flatten, gnu::target_clones("avx512f", "avx2", "default")]] void deltaERange(const float* rgbaA, const float* rgbaB, float* deltaE, std::size_t count) {
    using formulas::FastFloatMath;
    for (std::size_t i = 0; i < count; ++i) {
        const float* pa = rgbaA + 4 * i;
        const float* pb = rgbaB + 4 * i;
        float xyzA[3], xyzB[3];
        formulas::linearSrgbToXyz(pa[0], pa[1], pa[2], xyzA);
        formulas::linearSrgbToXyz(pb[0], pb[1], pb[2], xyzB);
        float la, aa, ba, lb, ab, bb;
        formulas::xyzToLab<float, FastFloatMath>(xyzA, la, aa, ba);
        formulas::xyzToLab<float, FastFloatMath>(xyzB, lb, ab, bb);
        deltaE[i] = formulas::ciede2000<float, FastFloatMath>(la, aa, ba, lb, ab, bb);
    }
}

ChunkSummary compareChunk(const Image& a, const Image& b, bool useAlpha, std::size_t begin,
                          std::size_t end, DeltaEMap& map) {
    float* deltaE = map.deltaE.data() + begin;
    deltaERange(a.rgba.data() + 4 * begin, b.rgba.data() + 4 * begin, deltaE, end - begin);
    ChunkSummary summary;
    for (std::size_t i = begin; i < end; ++i) {
        const bool covered = !useAlpha || (a.rgba[4 * i + 3] > kCoverageThreshold &&
                                           b.rgba[4 * i + 3] > kCoverageThreshold);
        map.covered[i] = covered ? 1 : 0;
        if (!covered) {
            map.deltaE[i] = 0.0f;
            continue;
        }
        summary.sum += map.deltaE[i];
        summary.max = std::max(summary.max, map.deltaE[i]);
        ++summary.pixels;
    }
    return summary;
}

// Runs work(chunk) for every chunk on up to workerCount threads; chunks are claimed in any
// order, so work must write only to its own chunk's outputs.
template <typename Work>
void forEachChunk(std::size_t chunkCount, unsigned workerCount, const Work& work) {
    unsigned workers = workerCount != 0 ? workerCount : std::thread::hardware_concurrency();
    workers = unsigned(std::clamp<std::size_t>(workers, 1, chunkCount));
    std::atomic<std::size_t> next{0};
    auto drain = [&] {
        for (std::size_t chunk = next++; chunk < chunkCount; chunk = next++) work(chunk);
    };
    std::vector<std::jthread> helpers;
    for (unsigned i = 1; i < workers; ++i) helpers.emplace_back(drain);
    drain();
}

double nearestRankPercentile95(const DeltaEMap& map, std::size_t coveredPixels) {
    std::vector<float> values;
    values.reserve(coveredPixels);
    for (std::size_t i = 0; i < map.deltaE.size(); ++i)
        if (map.covered[i]) values.push_back(map.deltaE[i]);
    // ceil(0.95 N) computed in integers: 1-based rank, 0-based index one less.
    const std::size_t rank = (95 * values.size() + 99) / 100;
    auto nth = values.begin() + std::ptrdiff_t(rank - 1);
    std::nth_element(values.begin(), nth, values.end());
    return *nth;
}

}  // namespace

Result<DeltaEMap> compareImages(const Image& a, const Image& b, bool useAlpha,
                                unsigned workerCount) {
    if (a.width != b.width || a.height != b.height)
        return Error{"image sizes differ: " + std::to_string(a.width) + "x" +
                     std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                     std::to_string(b.height)};
    const std::size_t pixelCount = a.pixelCount();
    if (a.rgba.size() != pixelCount * 4 || b.rgba.size() != pixelCount * 4)
        return Error{"malformed image: pixel data does not match its size"};

    DeltaEMap map;
    map.width = a.width;
    map.height = a.height;
    map.deltaE.resize(pixelCount);
    map.covered.resize(pixelCount);
    const std::size_t chunkCount = (pixelCount + kChunkPixels - 1) / kChunkPixels;
    std::vector<ChunkSummary> summaries(chunkCount);
    forEachChunk(chunkCount, workerCount, [&](std::size_t chunk) {
        const std::size_t begin = chunk * kChunkPixels;
        summaries[chunk] =
            compareChunk(a, b, useAlpha, begin, std::min(begin + kChunkPixels, pixelCount), map);
    });

    // Pooled in chunk order, whichever thread did which chunk.
    double sum = 0;
    for (const ChunkSummary& summary : summaries) {
        sum += summary.sum;
        map.stats.max = std::max(map.stats.max, double(summary.max));
        map.stats.pixels += summary.pixels;
    }
    if (map.stats.pixels > 0) {
        map.stats.mean = sum / double(map.stats.pixels);
        map.stats.p95 = nearestRankPercentile95(map, map.stats.pixels);
    }
    return map;
}

}  // namespace matevo
