#include "color/ImageDifference.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "color/Coverage.h"
#include "color/DeltaEPooling.h"
#include "color/detail/ColorFormulas.h"
#include "color/detail/FastFloatMath.h"
#include "color/detail/VectorisedKernel.h"
#include "common/HugePages.h"
#include "common/ParallelFor.h"

namespace matevo {
namespace {

// Fixed chunk size: the partial sums, and so the mean, never depend on the thread count.
constexpr std::size_t kChunkPixels = 16384;
// Small enough that a sphere's background rows and row ends make whole blocks to skip.
constexpr std::size_t kBlockPixels = 256;

// Float math through the shared formulas: flattened, this loop has no calls and no branches, so
// the compiler vectorises it.
MATEVO_VECTORISED_KERNEL void deltaERange(const float* rgbaA, const float* rgbaB, float* deltaE,
                                          std::size_t count) {
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

bool anyCoveredInBoth(const float* rgbaA, const float* rgbaB, std::size_t begin, std::size_t end) {
    bool any = false;
    for (std::size_t i = begin; i < end; ++i) {
        const bool coveredA = isCovered(rgbaA[4 * i + 3]);
        const bool coveredB = isCovered(rgbaB[4 * i + 3]);
        any |= coveredA & coveredB;  // `&`, not `&&`: no branch per pixel
    }
    return any;
}

DeltaEPooling compareChunk(const Image& a, const Image& b, bool useAlpha, std::size_t begin,
                           std::size_t end, ErrorMap& map) {
    const float* rgbaA = a.rgba.data();
    const float* rgbaB = b.rgba.data();
    float* deltaE = map.values.data();
    std::uint8_t* covered = map.covered.data();
    DeltaEPooling pooling;
    // In blocks small enough that the coverage pass finds the block's alpha still in cache.
    for (std::size_t block = begin; block < end; block += kBlockPixels) {
        const std::size_t blockEnd = std::min(block + kBlockPixels, end);
        if (useAlpha && !anyCoveredInBoth(rgbaA, rgbaB, block, blockEnd)) {
            // Background in one image or the other: nothing to measure, nothing to pool.
            std::fill(deltaE + block, deltaE + blockEnd, 0.0f);
            std::fill(covered + block, covered + blockEnd, std::uint8_t(0));
            continue;
        }
        deltaERange(rgbaA + 4 * block, rgbaB + 4 * block, deltaE + block, blockEnd - block);
        for (std::size_t i = block; i < blockEnd; ++i) {
            const bool coveredA = isCovered(rgbaA[4 * i + 3]);
            const bool coveredB = isCovered(rgbaB[4 * i + 3]);
            const bool bothCover = coveredA & coveredB;
            const bool inBoth = !useAlpha || bothCover;
            // Branch-free: coverage along a sphere's rim is hard to predict.
            deltaE[i] = inBoth ? deltaE[i] : 0.0f;
            covered[i] = inBoth ? 1 : 0;
            pooling.add(deltaE[i], inBoth);
        }
    }
    return pooling;
}

}  // namespace

Status requireComparable(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        return badInput("image sizes differ: " + std::to_string(a.width) + "x" +
                        std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                        std::to_string(b.height));
    if (a.rgba.size() != a.pixelCount() * 4 || b.rgba.size() != b.pixelCount() * 4)
        return internalError("malformed image: pixel data does not match its size");
    return Ok{};
}

Result<ErrorMap> compareImages(const Image& a, const Image& b, bool useAlpha,
                               unsigned workerCount) {
    if (auto comparable = requireComparable(a, b); !comparable) return comparable.error();
    const std::size_t pixelCount = a.pixelCount();

    ErrorMap map;
    map.metric = ImageMetric::DeltaE00;
    map.width = a.width;
    map.height = a.height;
    resizeOnHugePages(map.values, pixelCount);
    resizeOnHugePages(map.covered, pixelCount);
    const std::size_t chunkCount = (pixelCount + kChunkPixels - 1) / kChunkPixels;
    std::vector<DeltaEPooling> chunks(chunkCount);
    parallelForChunks(
        int(chunkCount),
        [&](int chunk) {
            const std::size_t begin = std::size_t(chunk) * kChunkPixels;
            chunks[std::size_t(chunk)] = compareChunk(
                a, b, useAlpha, begin, std::min(begin + kChunkPixels, pixelCount), map);
        },
        {}, workerCount);

    // Pooled in chunk order, whichever thread did which chunk.
    DeltaEPooling pooling;
    for (const DeltaEPooling& chunk : chunks) pooling.merge(chunk);
    map.stats = pooling.finish(map.values, map.covered);
    return map;
}

}  // namespace matevo
