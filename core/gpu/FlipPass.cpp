#include "gpu/FlipPass.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <vector>

#include <shaders/kFlipCombineSpirv.h>
#include <shaders/kFlipRowFilterSpirv.h>

#include "gpu/CommandRunner.h"
#include "gpu/ImageBatch.h"

namespace matevo::gpu {
namespace {

constexpr uint32_t kRowGroupSize = 8;       // local_size_x and _y in FlipRowFilter.comp
constexpr uint32_t kCombineGroupSize = 64;  // local_size_x in FlipCombine.comp
// Pixels each invocation filters, and how many at a time (kRun and kBlock in
// shaders/FlipCommon.glsl). Only a block is unrolled, so the blocks set lavapipe's compile time
// and the runs the loads per output; docs/flip.md has the measured trade-off.
constexpr uint32_t kRun = 32;
constexpr uint32_t kRowBlock = 8;
constexpr uint32_t kCombineBlock = 4;
constexpr VkDeviceSize kPlaneFloatsPerPixel = 8;  // two vec4 (planeIndex in FlipCommon.glsl)
constexpr int kMaxFlipFilterRadius = 20;          // kMaxFilterRadius in shaders/FlipCommon.glsl
// The taps' uniform block (kMaxTapVectors vec4 in shaders/FlipCommon.glsl).
constexpr std::size_t kTapBufferFloats = 4 * ((7 * (2 * kMaxFlipFilterRadius + 1) + 3) / 4);

struct PushConstants {
    int32_t width;
    int32_t height;
    uint32_t referenceImage;
    uint32_t firstCandidate;
    float maxColorDistance;
};

// In the order shaders/FlipCommon.glsl reads them.
std::vector<float> tapsOf(const flip::CsfKernels& csf, const flip::FeatureKernels& feature) {
    std::vector<float> taps;
    for (const auto* filter :
         {&csf.achromatic, &csf.redGreen, &csf.blueYellow[0], &csf.blueYellow[1], &feature.gaussian,
          &feature.firstDerivative, &feature.secondDerivative})
        taps.insert(taps.end(), filter->begin(), filter->end());
    return taps;
}

uint32_t groups(uint32_t items, uint32_t perGroup) { return (items + perGroup - 1) / perGroup; }

PushConstants pushConstantsOf(const FlipBatch& batch) {
    return {batch.width, batch.height, batch.referenceImage, batch.firstCandidate,
            float(flip::maxColorDistance())};
}

// The row pass: runs of a row × rows × images.
void recordRowPass(VkCommandBuffer commands, const ComputeKernel& rowFilter,
                   const FlipBatch& batch) {
    const PushConstants constants = pushConstantsOf(batch);
    rowFilter.record(commands, &constants,
                     groups(groups(uint32_t(batch.width), kRun), kRowGroupSize),
                     groups(uint32_t(batch.height), kRowGroupSize), batch.candidateCount + 1);
}

// The combination: columns × runs of a column × candidates.
void recordCombination(VkCommandBuffer commands, const ComputeKernel& combine,
                       const FlipBatch& batch) {
    const PushConstants constants = pushConstantsOf(batch);
    combine.record(commands, &constants, groups(uint32_t(batch.width), kCombineGroupSize),
                   groups(uint32_t(batch.height), kRun), batch.candidateCount);
}

}  // namespace

Result<FlipPass> FlipPass::create(const Device& device) {
    if (!device.int64())
        return environmentError(
            "FLIP on the GPU needs 64-bit integers in shaders (shaderInt64), which " +
            device.name() + " does not have");
    FlipPass pass;
    pass.device_ = &device;
    // The kernels follow the viewing condition: prepare() makes them for the first batch.
    return pass;
}

Result<const FlipPass::Kernels*> FlipPass::kernelsFor(int csfRadius, int featureRadius) {
    for (const Kernels& kernels : kernels_)
        if (kernels.csfRadius == csfRadius && kernels.featureRadius == featureRadius)
            return &kernels;
    // constant_id 0 to 3 in shaders/FlipCommon.glsl.
    const auto constants = [&](uint32_t block) {
        return std::array<uint32_t, 4>{uint32_t(csfRadius), uint32_t(featureRadius), kRun, block};
    };
    const auto rowConstants = constants(kRowBlock);
    const auto combineConstants = constants(kCombineBlock);
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const VkDescriptorType uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    // Images and planes are read as texel buffers (see bind); the row pass writes the planes.
    auto rowFilter =
        ComputeKernel::create(*device_, kFlipRowFilterSpirv, {texels, texels, uniform, storage},
                              sizeof(PushConstants), rowConstants);
    if (!rowFilter) return rowFilter.error();
    // The combination reads the planes, not the images: bindings 0 and 1 are bound, not read.
    auto combine = ComputeKernel::create(*device_, kFlipCombineSpirv,
                                         {texels, texels, uniform, texels, storage},
                                         sizeof(PushConstants), combineConstants);
    if (!combine) return combine.error();
    kernels_.push_back(
        {csfRadius, featureRadius, std::move(rowFilter).value(), std::move(combine).value()});
    return &kernels_.back();
}

Result<UniqueBufferView> FlipPass::pixelView(const Buffer& buffer) const {
    constexpr VkDeviceSize kTexelBytes = 4 * sizeof(float);
    if (buffer.size() / kTexelBytes > device_->maxTexelBufferElements())
        return environmentError("FLIP on the GPU: a batch of " +
                                std::to_string(buffer.size() >> 20) + " MiB is more than " +
                                device_->name() + " reads as one texel buffer");
    return createTexelView(*device_, buffer, VK_FORMAT_R32G32B32A32_SFLOAT);
}

Status FlipPass::prepare(const FlipBatch& batch, const FlipSettings& settings) {
    if (!(settings.pixelsPerDegree > 0.0) || settings.pixelsPerDegree > 1000.0)
        return badInput("pixels per degree must be in (0, 1000]");
    if (!taps_.handle() || settings.pixelsPerDegree != tapsPixelsPerDegree_) {
        auto csf = flip::makeCsfKernels(settings.pixelsPerDegree);
        auto feature = flip::makeFeatureKernels(settings.pixelsPerDegree);
        if (std::max(csf.radius, feature.radius) > kMaxFlipFilterRadius)
            return badInput("FLIP on the GPU takes at most " +
                            std::to_string(kMaxFlipFilterRadius) +
                            "-pixel filters (about 148 pixels per degree)");
        std::vector<float> taps = tapsOf(csf, feature);
        taps.resize(kTapBufferFloats, 0.0f);  // the whole uniform block the shaders declare
        auto buffer = Buffer::create(*device_, taps.size() * sizeof(float),
                                     VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::Upload);
        if (!buffer) return buffer.error();
        std::memcpy(buffer->bytes().data(), taps.data(), taps.size() * sizeof(float));
        taps_ = std::move(buffer).value();
        csf_ = std::move(csf);
        feature_ = std::move(feature);
        tapsPixelsPerDegree_ = settings.pixelsPerDegree;
    }
    // The reference's planes and each candidate's.
    const VkDeviceSize planeBytes = VkDeviceSize(batch.width) * VkDeviceSize(batch.height) *
                                    (batch.candidateCount + 1) * kPlaneFloatsPerPixel *
                                    sizeof(float);
    if (!planes_.handle() || planes_.size() < planeBytes) {
        auto buffer = Buffer::create(
            *device_, planeBytes,
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
            MemoryUse::DeviceLocal);
        if (!buffer) return buffer.error();
        auto view = pixelView(*buffer);
        if (!view) return view.error();
        planesView_ = std::move(view).value();  // before the buffer it viewed goes
        planes_ = std::move(buffer).value();
    }
    // The images' views: the batch's buffers may be new ones at every call.
    auto referenceView = pixelView(*batch.reference);
    if (!referenceView) return referenceView.error();
    auto candidatesView = pixelView(*batch.candidates);
    if (!candidatesView) return candidatesView.error();
    referenceView_ = std::move(referenceView).value();
    candidatesView_ = std::move(candidatesView).value();
    return Ok{};
}

Result<const FlipPass::Kernels*> FlipPass::bind(const FlipBatch& batch,
                                                const FlipSettings& settings) {
    if (auto prepared = prepare(batch, settings); !prepared) return prepared.error();
    auto kernels = kernelsFor(csf_.radius, feature_.radius);
    if (!kernels) return kernels.error();
    const ComputeKernel& rowFilter = (*kernels)->rowFilter;
    const ComputeKernel& combine = (*kernels)->combine;
    for (const ComputeKernel* kernel : {&rowFilter, &combine}) {
        kernel->descriptors().bindTexelBuffer(0, referenceView_.get());
        kernel->descriptors().bindTexelBuffer(1, candidatesView_.get());
        kernel->bindBuffer(2, taps_);
    }
    rowFilter.bindBuffer(3, planes_);
    combine.descriptors().bindTexelBuffer(3, planesView_.get());
    combine.bindBuffer(4, *batch.error);
    return kernels;
}

Status FlipPass::record(VkCommandBuffer commands, const FlipBatch& batch,
                        const FlipSettings& settings) {
    if (batch.candidateCount == 0 || batch.width <= 0 || batch.height <= 0) return Ok{};
    auto kernels = bind(batch, settings);
    if (!kernels) return kernels.error();
    recordRowPass(commands, (*kernels)->rowFilter, batch);
    computeWriteToComputeReadBarrier(commands);
    recordCombination(commands, (*kernels)->combine, batch);
    return Ok{};
}

Status FlipPass::compile(CommandRunner& runner, const FlipSettings& settings) {
    const ImageBatchShape shape{1, 1, 1};
    auto image = createBatchBuffer(*device_, shape, 4, MemoryUse::DeviceLocal);
    auto map = createBatchBuffer(*device_, shape, 1, MemoryUse::DeviceLocal);
    for (const auto* buffer : {&image, &map})
        if (!*buffer) return buffer->error();
    // One pixel, whatever its value: only the dispatches matter.
    const FlipBatch batch{&*image, &*image, &*map, 1, 1, 1, 0, 0};
    auto kernels = bind(batch, settings);
    if (!kernels) return kernels.error();
    Status compiled = Ok{};
    for (const bool rowPass : {true, false}) {
        auto commands = runner.begin();
        if (!commands) {
            compiled = commands.error();
            break;
        }
        if (rowPass) {
            recordRowPass(*commands, (*kernels)->rowFilter, batch);
        } else {
            computeWriteToComputeReadBarrier(*commands);  // the planes of the last submission
            recordCombination(*commands, (*kernels)->combine, batch);
        }
        if (compiled = runner.submitAndWait(); !compiled) break;
    }
    // The views of this pixel go with it; record makes the batch's own.
    referenceView_ = {};
    candidatesView_ = {};
    return compiled;
}

}  // namespace matevo::gpu
