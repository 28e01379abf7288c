#pragma once
// Up-front estimates of the memory and processor time of large work, so that the user sees the
// cost before it is spent and work past the memory limit (common/MemoryBudget.h,
// --max-memory) is refused before it starts instead of ending in the OOM killer; the limit is
// then enforced while the work runs (MemoryLimitWatch.h).
//
// Times are processor seconds on the CPU renderer, from per-pixel costs measured on a two-core
// x86-64 machine (lavapipe costs about the same; a real GPU renders much faster). They are
// meant to tell a minute from an hour, not to the second.
#include <cstdint>
#include <string>
#include <vector>

#include "export/ExportSet.h"

namespace matevo {
struct Mesh;
}  // namespace matevo

namespace matevo::cli {

struct WorkEstimate {
    std::string what;         // what the user asked for, e.g. "--out: 2000 candidates at 256x256"
    std::uint64_t bytes = 0;  // peak memory
    double seconds = 0;       // processor time
};

// `render --size N`
WorkEstimate renderEstimate(int size);
// `evolve`, with --out at `size` when size > 0 (the GA alone otherwise).
WorkEstimate evolveEstimate(int population, int generations, int size);
// `variants`: the search at fitnessSize, then the set checked and written at size; in
// `blocks` blocks of `count` variants, one after another (memory of one, time of all); every
// material rendered and measured under each of `lightings` lightings.
WorkEstimate variantsEstimate(int count, int size, int fitnessSize, int maxEvaluations,
                              int population, int blocks = 1, int lightings = 1);
// `experiment`: gaRuns GA runs, each scored by one render at size; imageRuns of them (--metric
// image) also render every individual at fitnessSize.
WorkEstimate experimentEstimate(long long gaRuns, int population, int generations, int size,
                                long long imageRuns = 0, int fitnessSize = 0);
// `compare` of two decoded width x height images (decoding is checked when each is read).
WorkEstimate compareEstimate(int width, int height, bool flip);
// What a scene or an export draws beside its pictures: the mesh and the textures.
struct SceneContents {
    std::uint64_t meshVertices = 0;
    std::uint64_t meshTriangles = 0;
    std::uint64_t texturePixels = 0;  // textures and every environment level, in all
};
// `mesh` may be null (a built-in sphere: next to nothing).
SceneContents sceneContentsOf(const Mesh* mesh, const SceneTextures& textures);
// `scene`: a width x height picture of `instances` instances. The Vulkan device's images and
// buffers are counted as host memory, as they are on a CPU device (lavapipe); a GPU holds
// them in its own memory, so there the estimate is high.
WorkEstimate sceneEstimate(int width, int height, std::uint64_t instances,
                           const SceneContents& contents);
// `export` of `materials` materials, each fitted with fitRenders renders at fitSize and
// reported at reportSize (the report keeps two renders and a ΔE00 map of each), and the
// mesh of `instances` instances when the arrangement has one.
WorkEstimate exportEstimate(std::uint64_t materials, int fitSize, int fitRenders, int reportSize,
                            std::uint64_t instances, const SceneContents& contents);

// `export` of `materials` (they share textures) with `settings`, arranged as `asset` says: the
// textures are read here to be counted (fitting reads them again; they are small next to the
// renders); textures that cannot be read count as none, and the fit fails naming them. Also
// what the editor's Export set checks before it starts.
WorkEstimate exportSetEstimate(const std::vector<MaterialFile>& materials,
                               const ExportSettings& settings, const GltfAsset& asset);

// Where a command's work begins. Throws UsageError (exit 2, one line) when the estimate is past
// the memory limit; prints it as a notice when the work is large (1 GiB or half a minute), so
// the user can stop it. Then holds the work to the limit while it runs (MemoryLimitWatch.h),
// stopping it here already when the command is past the limit (reading its inputs).
void beginEstimatedWork(const WorkEstimate& estimate);

// "40 s", "12 min", "3.5 h"
std::string describeDuration(double seconds);

}  // namespace matevo::cli
