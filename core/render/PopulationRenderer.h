#pragma once
// The one way matevo turns materials into pictures: render a batch of materials on the test
// sphere, or evaluate a population (target and candidates rendered, per-pixel ΔE00 and, when
// asked, ꟻLIP of each candidate against the target). Heatmaps are coloured from the maps by
// whoever shows them (core/color for files, the editor window's shader). Two implementations
// draw the same pictures to within the cross-check of tests/gpu: CpuPopulationRenderer (the
// reference) and gpu::GpuPopulationRenderer. Callers get one from gpu::createPopulationRenderer,
// the only place that chooses between them, and talk to it through this interface only. An
// instance is used from one thread at a time.
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "color/Flip.h"
#include "color/ImageDifference.h"
#include "color/ImageMetric.h"
#include "common/Choice.h"
#include "common/Image.h"
#include "common/Result.h"
#include "material/MaterialInstance.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo {

namespace gpu {
struct DisplayTile;
}

enum class RenderBackend { Gpu, Cpu };
// The back ends by name: --backend, reports' "made_by".
inline constexpr std::array<Choice<RenderBackend>, 2> kRenderBackends{{
    {RenderBackend::Gpu, "gpu", "GPU"},
    {RenderBackend::Cpu, "cpu", "CPU"},
}};

struct PopulationEvaluation {
    Image target;
    std::vector<Image> candidates;  // empty unless EvaluationOptions::candidateImages
    // Candidate vs target, one map per candidate for each metric computed: ΔE00 always, ꟻLIP
    // with EvaluationOptions::flip.
    std::map<ImageMetric, std::vector<ErrorMap>> errors;
};

struct EvaluationOptions {
    // ꟻLIP maps too (e.g. for a ꟻLIP fitness or heatmap), at this viewing condition.
    bool flip = false;
    FlipSettings flipSettings;
    // The map whose heatmap a window shows, which evaluateIntoTiles puts into the tiles: ΔE00,
    // or ꟻLIP (with `flip`).
    ImageMetric heatmapMetric = ImageMetric::DeltaE00;
    // The candidates' renders besides the maps (fitness needs only the maps).
    bool candidateImages = true;
};

// Display tiles on a window's device (gpu::DisplayTile, made in core/gpu) for evaluateIntoTiles
// and renderIntoTile to fill, and the copy of host pictures into them (gpu::uploadToTiles) that a
// renderer which does not draw on that device uses.
struct TileOutput {
    std::span<const gpu::DisplayTile* const> tiles;
    // tiles[i] gets pictures[i], and maps[i] when maps is not empty.
    std::function<Status(std::span<const Image> pictures, std::span<const ErrorMap> maps)> upload;
};

class PopulationRenderer {
public:
    virtual ~PopulationRenderer() = default;

    // "GPU (llvmpipe)" or "CPU", for status lines and reports.
    virtual std::string name() const = 0;
    // Which back end this is: the GPU asked for may have fallen back to the CPU.
    virtual RenderBackend backend() const = 0;

    // The textures every later render uses (a preset with other textures was chosen).
    virtual Status setTextures(const SceneTextures& textures) = 0;

    // One size x size image per material, in order.
    virtual Result<std::vector<Image>> render(std::span<const MaterialInstance> materials,
                                              const SceneSettings& scene, int size) = 0;

    // The target's render is kept between calls and drawn again only when the target, the
    // scene, the size or the textures change, so a GA can call this every generation.
    virtual Result<PopulationEvaluation> evaluate(const MaterialInstance& target,
                                                  std::span<const MaterialInstance> candidates,
                                                  const SceneSettings& scene, int size,
                                                  const EvaluationOptions& options = {}) = 0;

    // Gets ready now what evaluations with `options` need (the GPU compiles its ꟻLIP pipelines,
    // one submission each), so that a window drawing on the same queue waits for one at a time
    // rather than for all of them at its first ꟻLIP tiles. Optional: evaluate does it too.
    virtual Status prepareFor(const EvaluationOptions& options);

    // As evaluate, and candidate i's picture and error map go into tiles.tiles[i]: the map of
    // options.heatmapMetric when it is computed, ꟻLIP where pooled and "not covered" (negative,
    // as ΔE00's) elsewhere, else the ΔE00 map. The GPU renderer on the tiles' device copies them
    // in its own submission (it is made on that device); any other hands its host copies to
    // tiles.upload.
    virtual Result<PopulationEvaluation> evaluateIntoTiles(
        const MaterialInstance& target, std::span<const MaterialInstance> candidates,
        const SceneSettings& scene, int size, const EvaluationOptions& options,
        const TileOutput& tiles);

    // Renders `material` into tile.tiles[0]'s picture, which is size x size.
    virtual Status renderIntoTile(const MaterialInstance& material, const SceneSettings& scene,
                                  int size, const TileOutput& tile);
};

// What a kept target render was drawn from; both implementations compare against it.
struct TargetKey {
    MaterialInstance material;
    SceneSettings scene;
    int size = 0;

    bool operator==(const TargetKey&) const = default;
};

}  // namespace matevo
