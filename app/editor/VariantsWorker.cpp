#include "VariantsWorker.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "experiment/Experiment.h"
#include "scene/SceneTextures.h"

namespace matevo::editor {

VariantsWorker::VariantsWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer)
    : onUpdate_(std::move(onUpdate)), rendererRequest_(std::move(renderer)) {
    rendererRequest_.cancelled = [this] { return stopping_.load(); };
}

VariantsWorker::~VariantsWorker() {
    stopping_.store(true);
    if (thread_.joinable()) thread_.join();
}

bool VariantsWorker::start(VariantsJob job) {
    if (busy_.exchange(true)) return false;
    if (thread_.joinable()) thread_.join();  // the previous job has finished
    progress_.store(0.0f);
    thread_ = std::thread([this, job = std::move(job)] {
        VariantsResult result = compute(job);
        {
            std::lock_guard lock(mutex_);
            result_ = std::move(result);
        }
        busy_.store(false);
        onUpdate_();
    });
    return true;
}

std::optional<VariantsResult> VariantsWorker::takeResult() {
    std::lock_guard lock(mutex_);
    return std::exchange(result_, std::nullopt);
}

bool VariantsWorker::hasResult() {
    std::lock_guard lock(mutex_);
    return result_.has_value();
}

VariantsResult VariantsWorker::compute(const VariantsJob& job) {
    const auto started = std::chrono::steady_clock::now();
    VariantsResult result{job.preset, {job.request, kOutputSize, kFitnessSize}, {}, {}};
    auto textures = loadSceneTextures(job.preset, job.presetFile);
    if (!textures) {
        result.error = textures.error().message;
        return result;
    }
    const Preset& preset = job.preset;
    std::shared_ptr<PopulationRenderer> renderer =
        gpu::createPopulationRenderer(rendererRequest_, *textures);
    // As `matevo variants` measures: on the images as the PNG files of a saved set hold them.
    auto renderAt = [&](int size) {
        return asStoredInPng(
            renderGenomesWith(renderer, preset.family, preset.baseKappa, preset.scene, size));
    };
    VariantSearchSettings settings;
    auto search = VariantSearch::start(preset.family, preset.target, job.request, settings,
                                       renderAt(kFitnessSize));
    if (!search) {
        result.error = search.error().message;
        return result;
    }
    const double wanted = double(job.request.count + settings.spare);
    while (!(*search)->finished()) {
        if (auto stepped = (*search)->step(); !stepped) {
            result.error = stepped.error().message;
            return result;
        }
        const VariantSearchProgress& progress = (*search)->progress();
        progress_.store(float(std::max(double(progress.archived) / wanted,
                                       double(progress.evaluations) / settings.maxEvaluations)));
        onUpdate_();
    }
    auto set = chooseVariantSet((*search)->archive(), job.request, preset.target,
                                renderAt(kOutputSize));
    if (!set) {
        result.error = set.error().message;
        return result;
    }
    result.set = std::move(set).value();
    result.run.evaluations = (*search)->progress().evaluations;
    result.run.archived = (*search)->progress().archived;
    result.run.closestDeltaE = (*search)->progress().closestDeltaE;
    result.run.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

}  // namespace matevo::editor
