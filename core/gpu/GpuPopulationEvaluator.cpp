#include "gpu/GpuPopulationEvaluator.h"

namespace matevo::gpu {

Result<GpuPopulationEvaluator> GpuPopulationEvaluator::create(
    const Device& device, const FgdTables& tables, const SceneTextures& textures,
    const DeltaE00Pass::Colormap& colormap) {
    auto runner = CommandRunner::create(device);
    if (!runner) return runner.error();
    auto renderer = GpuSphereRenderer::create(device, *runner, tables, textures);
    if (!renderer) return renderer.error();
    auto pass = DeltaE00Pass::create(device, colormap);
    if (!pass) return pass.error();
    GpuPopulationEvaluator evaluator;
    evaluator.device_ = &device;
    evaluator.runner_ = std::move(runner).value();
    evaluator.renderer_ = std::move(renderer).value();
    evaluator.deltaEPass_ = std::move(pass).value();
    return evaluator;
}

Status GpuPopulationEvaluator::ensureBuffers(const ImageBatchShape& shape) {
    if (shape.width == bufferShape_.width && shape.height == bufferShape_.height &&
        shape.count == bufferShape_.count)
        return Ok{};
    auto renders = createBatchBuffer(*device_, {shape.width, shape.height, shape.count + 1}, 4,
                                     MemoryUse::Readback);
    auto deltaE = createBatchBuffer(*device_, shape, 1, MemoryUse::Readback);
    auto heatmaps = createBatchBuffer(*device_, shape, 4, MemoryUse::Readback);
    for (const auto* buffer : {&renders, &deltaE, &heatmaps})
        if (!*buffer) return buffer->error();
    renders_ = std::move(renders).value();
    deltaE_ = std::move(deltaE).value();
    heatmaps_ = std::move(heatmaps).value();
    bufferShape_ = shape;
    return Ok{};
}

Result<PopulationEvaluation> GpuPopulationEvaluator::evaluate(
    const MaterialInstance& target, std::span<const MaterialInstance> candidates,
    const SceneSettings& scene, int size, const HeatmapRange& range) {
    if (size <= 0) return Error{"GPU render: image size must be positive"};
    const ImageBatchShape shape{size, size, uint32_t(candidates.size())};
    if (auto ready = ensureBuffers(shape); !ready) return ready.error();

    std::vector<MaterialInstance> materials;  // the target first, then the candidates
    materials.reserve(candidates.size() + 1);
    materials.push_back(target);
    materials.insert(materials.end(), candidates.begin(), candidates.end());

    auto commands = runner_.begin();
    if (!commands) return commands.error();
    if (auto recorded = renderer_.record(*commands, materials, scene, size, renders_); !recorded)
        return recorded.error();
    if (!candidates.empty()) {
        computeWriteToComputeReadBarrier(*commands);
        deltaEPass_.record(*commands, {&renders_, &renders_, &deltaE_, &heatmaps_,
                                       shape.pixelCount(), shape.count, 0, 1, range.minDeltaE,
                                       range.maxDeltaE});
    }
    computeWriteToHostReadBarrier(*commands);
    if (auto submitted = runner_.submitAndWait(); !submitted) return submitted.error();

    PopulationEvaluation evaluation;
    const ImageBatchShape renderShape{size, size, shape.count + 1};
    evaluation.target = downloadImage(renders_, renderShape, 0);
    for (uint32_t i = 0; i < shape.count; ++i) {
        evaluation.candidates.push_back(downloadImage(renders_, renderShape, i + 1));
        evaluation.deltaE.push_back(downloadDeltaEMap(deltaE_, shape, i));
        evaluation.heatmaps.push_back(downloadImage(heatmaps_, shape, i));
    }
    return evaluation;
}

Result<std::vector<Image>> GpuPopulationEvaluator::render(
    std::span<const MaterialInstance> materials, const SceneSettings& scene, int size) {
    return renderer_.render(runner_, materials, scene, size);
}

}  // namespace matevo::gpu
