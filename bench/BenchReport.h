#pragma once
// Figures reported by `matevo bench`. Each module adds its own in its own file.
#include <string>
#include <vector>

namespace matevo::bench {

struct BenchFigure {
    std::string key;   // JSON key, e.g. "ga_pop100_gen10_ms"
    double value = 0;  // a median
    std::string description;
};

using BenchReport = std::vector<BenchFigure>;

void benchGeneticAlgorithm(BenchReport& report);
void benchCpuRender(BenchReport& report);
void benchDeltaE00(BenchReport& report);
void benchGpuGrid(BenchReport& report);  // gpu_grid64_ms and cpu_grid64_ms
// `matevo bench --variants`: the variant search with and without its novelty (a few minutes).
void benchVariants(BenchReport& report);
void benchScene(BenchReport& report, int instances);  // scene_* frame times, raster renderer

}  // namespace matevo::bench
