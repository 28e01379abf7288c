#include "CompareMetricsWorker.h"

#include <exception>
#include <string>
#include <utility>

#include "documents/PresetTextures.h"
#include "experiment/Experiment.h"
#include "fitness/RenderGenomesWith.h"
#include "scene/SceneTextures.h"

namespace matevo::editor {

CompareMetricsWorker::CompareMetricsWorker(std::function<void()> onUpdate,
                                           gpu::RendererRequest renderer)
    : rendererRequest_(std::move(renderer)), job_(std::move(onUpdate)) {
    rendererRequest_.cancelled = [this] { return job_.stopping(); };
}

CompareMetricsWorker::~CompareMetricsWorker() = default;

bool CompareMetricsWorker::start(CompareMetricsJob job) {
    return job_.start([this, job = std::move(job)] { return compute(job); }, "the comparison");
}

CompareMetricsResult CompareMetricsWorker::compute(const CompareMetricsJob& job) {
    CompareMetricsResult result;
    auto textures = loadSceneTextures(job.preset, job.presetFile);
    if (!textures) {
        result.error = textures.error().message;
        return result;
    }
    const Preset& preset = job.preset;
    std::shared_ptr<PopulationRenderer> renderer =
        gpu::createPopulationRenderer(rendererRequest_, *textures);
    result.backend = renderer->name();
    const RenderGenomes render = renderGenomesWith(std::move(renderer), preset.family,
                                                   preset.baseKappa, preset.scene, kRenderSize);
    auto target = render(std::span<const Genome>(&preset.target, 1));
    if (!target) {
        result.error = target.error().message;
        return result;
    }

    ExperimentSettings settings;
    settings.runs = job.runs;
    settings.size = {preset.ga.population, preset.ga.generations};
    settings.seed = preset.ga.seed;
    const ExperimentTarget experimentTarget{preset.name, preset.family, preset.target, preset.ga};
    // Progress: the GA runs are the first half, the renders the second.
    // The paper's three genotype metrics only: nothing to render while evolving.
    auto evolved = evolveRuns(experimentTarget, settings, [&](int done, int total) {
        job_.reportProgress(0.5f * float(done) / float(total));
    });
    if (!evolved) {
        result.error = evolved.error().message;
        return result;
    }
    result.records = std::move(evolved).value();
    result.renders.resize(result.records.size());
    const auto scored = scoreRuns(
        result.records, target->front(), render, 16,
        [&](int done, int total) {
            job_.reportProgress(0.5f + 0.5f * float(done) / float(total));
        },
        [&](std::size_t index, const Image& image) { result.renders[index] = image; });
    if (!scored) result = {{}, {}, result.backend, scored.error().message};
    return result;
}

}  // namespace matevo::editor
