#include <cstdio>
#include <vector>

#include "BenchReport.h"
#include "Timing.h"
#include "color/Colormap.h"
#include "color/ImageDifference.h"
#include "evolve/GenomeSampling.h"
#include "gpu/GpuContext.h"
#include "gpu/GpuPopulationEvaluator.h"
#include "gpu/HeatmapColormap.h"
#include "material/FgdTableCache.h"
#include "scene/SphereRenderer.h"

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

// The same work on the CPU: render everything, ΔE00 of each candidate against the target, and
// the heatmap colouring.
double cpuGridMilliseconds(const Grid& grid) {
    const SceneTextures textures;
    const SceneSettings scene;
    return medianMilliseconds(3, [&] {
        const Image target = renderSphereCpu(grid.target, textures, scene, kImageSize);
        for (const MaterialInstance& candidate : grid.candidates) {
            const Image image = renderSphereCpu(candidate, textures, scene, kImageSize);
            auto map = compareImages(target, image);
            const Image heatmap = heatmapImage(*map, HeatmapSettings{});
        }
    });
}

}  // namespace

void benchGpuGrid(BenchReport& report) {
    const Grid grid = makeGrid();
    const auto colormap = gpu::heatmapColormap();
    (void)defaultFgdTables();  // table generation or loading is not part of the figure
    auto context = gpu::GpuContext::createHeadless();
    if (!context) {
        std::fprintf(stderr, "matevo bench: no usable Vulkan device (%s); gpu_grid64_ms skipped\n",
                     context.error().message.c_str());
    } else {
        auto evaluator = gpu::GpuPopulationEvaluator::create(context->device, defaultFgdTables(),
                                                             SceneTextures{}, colormap);
        if (!evaluator) {
            std::fprintf(stderr, "matevo bench: %s\n", evaluator.error().message.c_str());
        } else {
            bool failed = false;
            auto evaluateGrid = [&] {
                failed |= !evaluator->evaluate(grid.target, grid.candidates, SceneSettings{},
                                               kImageSize).ok();
            };
            evaluateGrid();  // lavapipe compiles the shaders on first use
            const double milliseconds = medianMilliseconds(kRepetitions, evaluateGrid);
            if (!failed)
                report.push_back({"gpu_grid64_ms", milliseconds,
                                  "64 candidates at 128^2 on " + context->device.name() +
                                      ": render + ΔE00 + heatmaps + read-back"});
        }
    }
    report.push_back({"cpu_grid64_ms", cpuGridMilliseconds(grid),
                      "the same grid on the CPU reference renderer and core/color"});
}

}  // namespace matevo::bench
