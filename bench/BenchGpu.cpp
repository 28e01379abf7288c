#include <cstdio>
#include <optional>
#include <vector>

#include "BenchReport.h"
#include "Timing.h"
#include "evolve/GenomeSampling.h"
#include "gpu/GpuPopulationRenderer.h"
#include "material/FgdTableCache.h"
#include "render/CpuPopulationRenderer.h"

namespace matevo::bench {
namespace {

constexpr int kCandidates = 64;
constexpr int kImageSize = 128;
constexpr int kRepetitions = 7;

// The editor's grid: a target and 64 candidates of one family.
struct Grid {
    MaterialInstance target;
    std::vector<MaterialInstance> candidates;
};

Grid makeGrid() {
    const MaterialFamily family{Coat::Clearcoat, Base::Conductor, true, TexturedLayer::None};
    const std::array<double, 3> kappa = {3.1, 2.9, 2.8};
    Random random(64);
    Grid grid{{randomGenome(family, random), family, kappa}, {}};
    for (int i = 0; i < kCandidates; ++i)
        grid.candidates.push_back({randomGenome(family, random), family, kappa});
    return grid;
}

// Medians of the grid's evaluation (render + ΔE00 + read-back) after one warm-up
// call (lavapipe compiles the shaders on first use); nullopt when an evaluation failed.
std::optional<WallAndCpu> gridTimes(PopulationRenderer& renderer, const Grid& grid,
                                    int repetitions) {
    bool failed = false;
    auto evaluateGrid = [&] {
        failed |=
            !renderer.evaluate(grid.target, grid.candidates, SceneSettings{}, kImageSize).ok();
    };
    evaluateGrid();
    const WallAndCpu times = medianWallAndCpu(repetitions, evaluateGrid);
    if (failed) return std::nullopt;
    return times;
}

}  // namespace

void benchGpuGrid(BenchReport& report) {
    const Grid grid = makeGrid();
    (void)defaultFgdTables();  // table generation or loading is not part of the figure
    std::optional<WallAndCpu> gpuGrid;
    auto gpuRenderer =
        gpu::GpuPopulationRenderer::createHeadless({}, defaultFgdTables(), SceneTextures{});
    if (!gpuRenderer) {
        std::fprintf(stderr, "matevo bench: no usable Vulkan device (%s); gpu_grid64_ms skipped\n",
                     gpuRenderer.error().message.c_str());
    } else {
        gpuGrid = gridTimes(**gpuRenderer, grid, kRepetitions);
        if (gpuGrid) {
            report.push_back({"gpu_grid64_ms", gpuGrid->wallMilliseconds,
                              "64 candidates at 128^2 on " + (*gpuRenderer)->name() +
                                  ": render + ΔE00 + read-back"});
            report.push_back({"gpu_grid64_cpu_ms", gpuGrid->cpuMilliseconds,
                              "the same, CPU time of every thread (lavapipe's too)"});
        }
        // The render's share of the grid: the rest is the ΔE00 pass and its read-back.
        const double renderMilliseconds = medianMilliseconds(kRepetitions, [&] {
            (void)(*gpuRenderer)->render(grid.candidates, SceneSettings{}, kImageSize);
        });
        report.push_back({"gpu_render64_ms", renderMilliseconds,
                          "the grid's 64 renders alone, with their read-back"});
    }
    CpuPopulationRenderer cpuRenderer{SceneTextures{}};
    const auto cpuGrid = gridTimes(cpuRenderer, grid, 3);
    if (!cpuGrid) return;
    report.push_back({"cpu_grid64_ms", cpuGrid->wallMilliseconds,
                      "the same grid on the CPU reference renderer and core/color"});
    report.push_back(
        {"cpu_grid64_cpu_ms", cpuGrid->cpuMilliseconds, "the same, CPU time of every thread"});
    if (gpuGrid)
        report.push_back({"gpu_over_cpu_grid64",
                          gpuGrid->wallMilliseconds / cpuGrid->wallMilliseconds,
                          "gpu_grid64_ms / cpu_grid64_ms of this run (< 1: the GPU is faster)"});
}

}  // namespace matevo::bench
