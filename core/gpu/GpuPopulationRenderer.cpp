#include "gpu/GpuPopulationRenderer.h"

#include "color/LabImage.h"
#include "common/ParallelFor.h"

namespace matevo::gpu {
namespace {

// The image's L*a*b* and alpha per pixel, 4 floats each (the sphere render's TargetLab).
Result<TexelBuffer> uploadLab(const Device& device, const Image& image) {
    const LabImage lab = toLabImage(image);
    auto buffer = createTexelBuffer(device, lab.pixelCount() * 4 * sizeof(float),
                                    VK_FORMAT_R32G32B32A32_SFLOAT);
    if (!buffer) return buffer.error();
    std::span<float> values = buffer->buffer.as<float>();
    for (std::size_t i = 0; i < lab.pixelCount(); ++i) {
        values[4 * i] = lab.lightness[i];
        values[4 * i + 1] = lab.greenRed[i];
        values[4 * i + 2] = lab.blueYellow[i];
        values[4 * i + 3] = image.rgba[4 * i + 3];
    }
    return buffer;
}

}  // namespace

Result<std::unique_ptr<GpuPopulationRenderer>> GpuPopulationRenderer::create(
    const Device& device, const FgdTables& tables, const SceneTextures& textures,
    CancelToken cancel) {
    auto runner = CommandRunner::create(device);
    if (!runner) return runner.error();
    auto renderer = GpuSphereRenderer::create(device, *runner, tables, textures);
    if (!renderer) return renderer.error();
    std::unique_ptr<GpuPopulationRenderer> result(new GpuPopulationRenderer);
    result->device_ = &device;
    result->tables_ = &tables;
    result->cancel_ = std::move(cancel);
    result->runner_ = std::move(runner).value();
    result->renderer_ = std::move(renderer).value();
    return result;
}

Result<std::unique_ptr<GpuPopulationRenderer>> GpuPopulationRenderer::createHeadless(
    const GpuContextOptions& options, const FgdTables& tables, const SceneTextures& textures,
    CancelToken cancel) {
    auto context = GpuContext::createHeadless(options);
    if (!context) return context.error();
    auto ownContext = std::make_unique<GpuContext>(std::move(context).value());
    auto result = create(ownContext->device, tables, textures, std::move(cancel));
    if (!result) return result.error();
    (*result)->ownContext_ = std::move(ownContext);
    return result;
}

std::string GpuPopulationRenderer::name() const { return "GPU (" + device_->name() + ")"; }

Status GpuPopulationRenderer::setTextures(const SceneTextures& textures) {
    auto renderer = GpuSphereRenderer::create(*device_, runner_, *tables_, textures);
    if (!renderer) return renderer.error();
    renderer_ = std::move(renderer).value();
    targetKey_.reset();
    return Ok{};
}

Status GpuPopulationRenderer::ensureBuffers(const ImageBatchShape& shape, bool flip) {
    const bool sameShape = shape.width == bufferShape_.width &&
                           shape.height == bufferShape_.height && shape.count == bufferShape_.count;
    if (!sameShape) {
        auto renders = createBatchBuffer(*device_, shape, 4, MemoryUse::Readback);
        auto deltaE = createBatchBuffer(*device_, shape, 1, MemoryUse::Readback);
        for (const auto* buffer : {&renders, &deltaE})
            if (!*buffer) return buffer->error();
        renders_ = std::move(renders).value();
        deltaE_ = std::move(deltaE).value();
        backgroundFilledFor_.reset();
        flip_ = {};
        bufferShape_ = shape;
    }
    if (flip && !flip_.handle()) {
        if (Status made = ensureFlipPass(); !made) return made;
        auto errors = createBatchBuffer(*device_, shape, 1, MemoryUse::Readback);
        if (!errors) return errors.error();
        flip_ = std::move(errors).value();
    }
    return Ok{};
}

Status GpuPopulationRenderer::ensureFlipPass() {
    if (flipPass_) return Ok{};
    auto pass = FlipPass::create(*device_);
    if (!pass) return pass.error();
    flipPass_ = std::move(pass).value();
    return Ok{};
}

Status GpuPopulationRenderer::prepareFor(const EvaluationOptions& options) {
    if (!options.flip) return Ok{};
    if (Status made = ensureFlipPass(); !made) return made;
    return flipPass_->compile(runner_, options.flipSettings);
}

Status GpuPopulationRenderer::renderTarget(const TargetKey& key) {
    const ImageBatchShape shape{key.size, key.size, 1};
    auto buffer = createBatchBuffer(*device_, shape, 4, MemoryUse::Readback);
    if (!buffer) return buffer.error();
    auto commands = runner_.begin();
    if (!commands) return commands.error();
    if (auto recorded =
            renderer_.record(*commands, std::span(&key.material, 1), key.scene, key.size, *buffer);
        !recorded)
        return recorded.error();
    computeWriteToHostReadBarrier(*commands);
    if (auto submitted = runner_.submitAndWait(); !submitted) return submitted.error();
    target_ = downloadImage(*buffer, shape, 0);
    auto lab = uploadLab(*device_, target_);
    if (!lab) return lab.error();
    targetRender_ = std::move(buffer).value();
    targetLab_ = std::move(lab).value();
    targetKey_ = key;
    return Ok{};
}

Result<PopulationEvaluation> GpuPopulationRenderer::evaluate(
    const MaterialInstance& target, std::span<const MaterialInstance> candidates,
    const SceneSettings& scene, int size, const EvaluationOptions& options) {
    return evaluateOnDevice(target, candidates, scene, size, options, {});
}

Result<PopulationEvaluation> GpuPopulationRenderer::evaluateIntoTiles(
    const MaterialInstance& target, std::span<const MaterialInstance> candidates,
    const SceneSettings& scene, int size, const EvaluationOptions& options,
    const TileOutput& tiles) {
    if (tiles.tiles.size() != candidates.size())
        return internalError("GPU render: one tile per candidate expected");
    return evaluateOnDevice(target, candidates, scene, size, options, tiles.tiles);
}

Result<PopulationEvaluation> GpuPopulationRenderer::evaluateOnDevice(
    const MaterialInstance& target, std::span<const MaterialInstance> candidates,
    const SceneSettings& scene, int size, const EvaluationOptions& options,
    std::span<const DisplayTile* const> tiles) {
    if (size <= 0) return internalError("GPU render: image size must be positive");
    if (cancel_.cancelled()) return cancelledError("rendering cancelled");
    const TargetKey key{target, scene, size};
    if (targetKey_ != key)
        if (auto rendered = renderTarget(key); !rendered) return rendered.error();
    PopulationEvaluation evaluation;
    evaluation.target = target_;
    evaluation.errors[ImageMetric::DeltaE00];  // also with no candidates
    if (candidates.empty()) return evaluation;

    const ImageBatchShape shape{size, size, uint32_t(candidates.size())};
    const bool flip = options.flip;
    if (auto ready = ensureBuffers(shape, flip); !ready) return ready.error();
    auto commands = runner_.begin();
    if (!commands) return commands.error();
    const TargetComparison comparison{targetLab_.view.get(), &deltaE_};
    const GpuSphereSamples::Key coverage = GpuSphereSamples::keyOf(scene, size);
    if (auto recorded = renderer_.record(*commands, candidates, scene, size, renders_, &comparison,
                                         backgroundFilledFor_ == coverage);
        !recorded)
        return recorded.error();
    // Also orders the target's render of an earlier submission before the ꟻLIP pass reads it.
    computeWriteToComputeReadBarrier(*commands);
    if (flip)
        if (auto recorded = flipPass_->record(
                *commands, {&targetRender_, &renders_, &flip_, size, size, shape.count, 0, 0},
                options.flipSettings);
            !recorded)
            return recorded.error();
    const Buffer& tileMaps = flip && options.heatmapMetric == ImageMetric::Flip ? flip_ : deltaE_;
    if (!tiles.empty()) recordCopiesToTiles(*commands, renders_, &tileMaps, shape, tiles);
    computeWriteToHostReadBarrier(*commands);
    backgroundFilledFor_.reset();  // unknown until the submission is done
    if (auto submitted = runner_.submitAndWait(); !submitted) return submitted.error();
    backgroundFilledFor_ = coverage;

    // The host copies, one candidate per chunk on every core: the GPU is done, and on lavapipe
    // these copies and the pooling of the maps are a sixth of the evaluation's CPU time.
    const std::size_t count = shape.count;
    evaluation.candidates.resize(options.candidateImages ? count : 0);
    std::vector<ErrorMap>& deltaE = evaluation.errors[ImageMetric::DeltaE00];
    deltaE.resize(count);
    std::vector<ErrorMap>* flipMaps = flip ? &evaluation.errors[ImageMetric::Flip] : nullptr;
    if (flipMaps) flipMaps->resize(count);
    parallelForChunks(int(count), [&](int chunk) {
        const auto i = uint32_t(chunk);
        if (options.candidateImages) evaluation.candidates[i] = downloadImage(renders_, shape, i);
        deltaE[i] = downloadErrorMap(deltaE_, shape, i, ImageMetric::DeltaE00);
        if (flipMaps) (*flipMaps)[i] = downloadErrorMap(flip_, shape, i, ImageMetric::Flip);
    });
    return evaluation;
}

Status GpuPopulationRenderer::renderIntoTile(const MaterialInstance& material,
                                             const SceneSettings& scene, int size,
                                             const TileOutput& tile) {
    if (cancel_.cancelled()) return cancelledError("rendering cancelled");
    if (tile.tiles.size() != 1) return internalError("GPU render: one tile expected");
    const ImageBatchShape shape{size, size, 1};
    auto buffer = createBatchBuffer(*device_, shape, 4, MemoryUse::DeviceLocal);
    if (!buffer) return buffer.error();
    auto commands = runner_.begin();
    if (!commands) return commands.error();
    if (auto recorded = renderer_.record(*commands, std::span(&material, 1), scene, size, *buffer);
        !recorded)
        return recorded.error();
    recordCopiesToTiles(*commands, *buffer, nullptr, shape, tile.tiles);
    return runner_.submitAndWait();
}

Result<std::vector<Image>> GpuPopulationRenderer::render(
    std::span<const MaterialInstance> materials, const SceneSettings& scene, int size) {
    if (size <= 0) return internalError("GPU render: image size must be positive");
    if (cancel_.cancelled()) return cancelledError("rendering cancelled");
    return renderer_.render(runner_, materials, scene, size);
}

}  // namespace matevo::gpu
