#include "BenchReport.h"
#include "Timing.h"
#include "color/Flip.h"
#include "color/ImageDifference.h"
#include "color/Srgb.h"

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "gpu/GpuContext.h"
#include "gpu/GpuImageComparer.h"

namespace matevo::bench {
namespace {

// The benchmark images, generated identically by bench/peers/skimage_de00.py: sRGB-encoded
// channel k of image `which` (0 or 1) is the top 24 bits of murmur3's fmix32 of 2 k + which,
// over 2^24; here decoded to linear, as compareImages takes renders. Alpha is 1 everywhere, so
// both sides score every pixel.
float encodedChannel(std::uint32_t channelIndex, std::uint32_t which) {
    std::uint32_t x = 2u * channelIndex + which;
    x ^= x >> 16;
    x *= 0x85ebca6bu;
    x ^= x >> 13;
    x *= 0xc2b2ae35u;
    x ^= x >> 16;
    return float(x >> 8) / float(1u << 24);
}

Image benchImage(int size, std::uint32_t which) {
    Image image(size, size);
    for (std::size_t pixel = 0; pixel < image.pixelCount(); ++pixel) {
        for (std::size_t c = 0; c < 3; ++c)
            image.rgba[4 * pixel + c] =
                float(srgbToLinear(encodedChannel(std::uint32_t(3 * pixel + c), which)));
        image.rgba[4 * pixel + 3] = 1.0f;
    }
    return image;
}

// How long the comparisons of one size are timed at least (ΔE00 and LDR-FLIP in turn, on the
// CPU and on the GPU): a call at 256² takes a few milliseconds, so 31 of each, one kind after
// the other, were a fraction of a second of a shared machine.
constexpr double kMinimumComparisonMilliseconds = 3000;

// Median Mpixel/s of compareImages on all cores, map and statistics included; also reports the
// mean ΔE00 so it can be checked against the peer's. LDR-FLIP on the same pair is timed in turn
// with it (bench/Timing.h), for the ratio of the two per-pixel costs.
double measure(BenchReport& report, int size, int repetitions) {
    const Image a = benchImage(size, 0);
    const Image b = benchImage(size, 1);
    double meanDeltaE = 0;
    const AlternatingTimes times = alternatingMedians(
        repetitions, kMinimumComparisonMilliseconds,
        [&] {
            auto map = compareImages(a, b);
            meanDeltaE = map ? map->stats.mean : -1;
        },
        [&] { (void)computeFlip(a, b); });
    const double milliseconds = times.first.wallMilliseconds;
    const double flipMilliseconds = times.second.wallMilliseconds;
    const std::string side = std::to_string(size);
    report.push_back({"de00_mean_" + side, meanDeltaE,
                      "mean dE00 of the " + side + "^2 benchmark pair (check against peer)"});
    const double megapixels = double(a.pixelCount()) / 1e6;
    const double rate = megapixels / (milliseconds / 1000.0);
    report.push_back({"de00_mpix_s_" + side, rate,
                      "CPU dE00 image comparison " + side + "^2, all cores (Mpixel/s)"});
    report.push_back({"flip_mpix_s_" + side, megapixels / (flipMilliseconds / 1000.0),
                      "CPU LDR-FLIP image comparison " + side + "^2, all cores (Mpixel/s)"});
    report.push_back({"flip_over_de00_" + side, flipMilliseconds / milliseconds,
                      "FLIP / dE00 time per pixel at " + side + "^2, same run (goal <= 3)"});
    return rate;
}

// The same pair on the GPU (lavapipe on our machines): upload, the compute pass, read-back and
// the statistics, for ΔE00 and for LDR-FLIP, after one warm-up call each, then timed in turn
// (bench/Timing.h). lavapipe compiles a pipeline at its first dispatch, so the first call of a
// comparer is reported apart, in CPU time of the whole process: the compile, from Mesa's
// shader cache when it holds the pipeline (MESA_SHADER_CACHE_DISABLE=true measures the
// uncached compile).
void measureGpu(BenchReport& report, gpu::GpuImageComparer& comparer, const std::string& device,
                int size, int repetitions, bool reportFirstCall) {
    const Image a = benchImage(size, 0);
    const std::vector<Image> b{benchImage(size, 1)};
    bool failed = false;
    auto deltaE = [&] { failed |= !comparer.compare(a, b).ok(); };
    auto flip = [&] { failed |= !comparer.compareFlip(a, b).ok(); };
    const double firstCallStart = processCpuMilliseconds();
    deltaE();
    const double deltaEFirstCall = processCpuMilliseconds() - firstCallStart;
    flip();
    const double flipFirstCall = processCpuMilliseconds() - firstCallStart - deltaEFirstCall;
    if (reportFirstCall) {
        report.push_back({"gpu_de00_first_call_cpu_ms", deltaEFirstCall,
                          "GPU dE00 first comparison " + std::to_string(size) +
                              "^2, pipeline compile included (process CPU ms)"});
        report.push_back({"gpu_flip_first_call_cpu_ms", flipFirstCall,
                          "GPU LDR-FLIP first comparison, the same (process CPU ms)"});
    }
    const AlternatingTimes times =
        alternatingMedians(repetitions, kMinimumComparisonMilliseconds, deltaE, flip);
    const WallAndCpu& deltaETimes = times.first;
    const WallAndCpu& flipTimes = times.second;
    const double deltaEMilliseconds = deltaETimes.wallMilliseconds;
    const double flipMilliseconds = flipTimes.wallMilliseconds;
    if (failed) {
        std::fprintf(stderr, "matevo bench: a GPU image comparison failed; gpu_* skipped\n");
        return;
    }
    const std::string side = std::to_string(size);
    const double megapixels = double(a.pixelCount()) / 1e6;
    report.push_back({"gpu_de00_mpix_s_" + side, megapixels / (deltaEMilliseconds / 1000.0),
                      "GPU dE00 image comparison " + side + "^2 on " + device +
                          ", upload + pass + read-back (Mpixel/s)"});
    report.push_back({"gpu_flip_mpix_s_" + side, megapixels / (flipMilliseconds / 1000.0),
                      "GPU LDR-FLIP image comparison " + side + "^2, the same (Mpixel/s)"});
    report.push_back({"gpu_flip_over_de00_" + side, flipMilliseconds / deltaEMilliseconds,
                      "GPU FLIP / dE00 time per pixel at " + side + "^2, same run"});
    report.push_back({"gpu_flip_over_de00_cpu_" + side,
                      flipTimes.cpuMilliseconds / deltaETimes.cpuMilliseconds,
                      "the same in process CPU time (steadier on a busy machine)"});
}

void benchGpuComparison(BenchReport& report) {
    auto context = gpu::GpuContext::createHeadless({});
    if (!context) {
        std::fprintf(stderr, "matevo bench: no usable Vulkan device (%s); gpu_* skipped\n",
                     context.error().message.c_str());
        return;
    }
    auto comparer = gpu::GpuImageComparer::create(context->device);
    if (!comparer) {
        std::fprintf(stderr, "matevo bench: %s; gpu_* skipped\n", comparer.error().message.c_str());
        return;
    }
    measureGpu(report, *comparer, context->device.name(), 256, 31, true);
    measureGpu(report, *comparer, context->device.name(), 2048, 5, false);
}

}  // namespace

void benchDeltaE00(BenchReport& report) {
    measure(report, 256, 101);
    const double large = measure(report, 2048, 5);
    report.push_back({"de00_mpix_s", large, "CPU dE00 image comparison, 2048^2 (Mpixel/s)"});
    benchGpuComparison(report);
}

}  // namespace matevo::bench
