#pragma once
// The one way matevo turns materials into pictures: render a batch of materials on the test
// sphere, or evaluate a population (target and candidates rendered, per-pixel ΔE00 and, when
// asked, ꟻLIP of each candidate against the target, heatmaps). Two implementations draw the same
// pictures to within the cross-check of tests/gpu: CpuPopulationRenderer (the reference) and
// gpu::GpuPopulationRenderer. Callers get one from gpu::createPopulationRenderer, the only place
// that chooses between them. An instance is used from one thread at a time.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "color/Colormap.h"
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

enum class RenderBackend { Gpu, Cpu };
// The back ends by name: --backend, reports' "made_by".
inline constexpr std::array<Choice<RenderBackend>, 2> kRenderBackends{{
    {RenderBackend::Gpu, "gpu", "GPU"},
    {RenderBackend::Cpu, "cpu", "CPU"},
}};

struct PopulationEvaluation {
    Image target;
    std::vector<Image> candidates;  // empty unless EvaluationOptions::candidateImages
    std::vector<DeltaEMap> deltaE;  // candidate vs target, over pixels covered in both
    std::vector<FlipMap> flip;    // the same with ꟻLIP; empty unless EvaluationOptions::wantsFlip
    std::vector<Image> heatmaps;  // EvaluationOptions::heatmapMetric colour-mapped, transparent
                                  // where not covered; empty unless EvaluationOptions::heatmaps
};

struct EvaluationOptions {
    HeatmapSettings heatmap;  // the ΔE00 range of the colour map (opacity is not used)
    // What the heatmaps show: ΔE00 through viridis over `heatmap`'s range, or ꟻLIP through
    // magma over its fixed range [0, 1].
    ImageMetric heatmapMetric = ImageMetric::DeltaE00;
    // ꟻLIP maps too (e.g. for a ꟻLIP fitness), at this viewing condition.
    bool flip = false;
    FlipSettings flipSettings;
    // What to hand back besides the ΔE00 maps: fitness needs neither, the grid only images.
    bool candidateImages = true;
    bool heatmaps = true;

    bool wantsFlip() const { return flip || (heatmaps && heatmapMetric == ImageMetric::Flip); }
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
};

// What a kept target render was drawn from; both implementations compare against it.
struct TargetKey {
    MaterialInstance material;
    SceneSettings scene;
    int size = 0;

    bool operator==(const TargetKey&) const = default;
};

}  // namespace matevo
