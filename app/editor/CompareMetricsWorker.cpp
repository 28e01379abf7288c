#include "CompareMetricsWorker.h"

#include <utility>

#include "experiment/Experiment.h"
#include "scene/SceneTextures.h"

namespace matevo::editor {

CompareMetricsWorker::CompareMetricsWorker(std::function<void()> onUpdate,
                                           gpu::RendererRequest renderer)
    : onUpdate_(std::move(onUpdate)), rendererRequest_(std::move(renderer)) {
    rendererRequest_.cancelled = [this] { return stopping_.load(); };
}

CompareMetricsWorker::~CompareMetricsWorker() {
    stopping_.store(true);
    if (thread_.joinable()) thread_.join();
}

bool CompareMetricsWorker::start(CompareMetricsJob job) {
    if (busy_.exchange(true)) return false;
    if (thread_.joinable()) thread_.join();  // the previous job has finished
    progress_.store(0.0f);
    thread_ = std::thread([this, job = std::move(job)] {
        CompareMetricsResult result = compute(job);
        {
            std::lock_guard lock(mutex_);
            result_ = std::move(result);
        }
        busy_.store(false);
        onUpdate_();
    });
    return true;
}

std::optional<CompareMetricsResult> CompareMetricsWorker::takeResult() {
    std::lock_guard lock(mutex_);
    return std::exchange(result_, std::nullopt);
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
    result.records = evolveRuns(experimentTarget, settings, [&](int done, int total) {
        progress_.store(0.5f * float(done) / float(total));
        onUpdate_();
    });
    result.renders.resize(result.records.size());
    const Status scored = scoreRuns(
        result.records, target->front(), render, 16,
        [&](int done, int total) {
            progress_.store(0.5f + 0.5f * float(done) / float(total));
            onUpdate_();
        },
        [&](std::size_t index, const Image& image) { result.renders[index] = image; });
    if (!scored) result = {{}, {}, result.backend, scored.error().message};
    return result;
}

}  // namespace matevo::editor
