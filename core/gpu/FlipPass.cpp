#include "gpu/FlipPass.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include <shaders/kFlipCombineSpirv.h>
#include <shaders/kFlipRowFilterSpirv.h>

#include "gpu/CommandRunner.h"

namespace matevo::gpu {
namespace {

constexpr uint32_t kWorkgroupSize = 64;      // local_size_x in both shaders
constexpr VkDeviceSize kPlanesPerImage = 7;  // kPlanes in shaders/FlipCommon.glsl
constexpr int kMaxFlipFilterRadius = 136;    // kMaxFilterRadius in shaders/FlipCommon.glsl
constexpr uint32_t kCombineRows = 8;         // kColumnRows in shaders/FlipCombine.comp
// The taps' uniform block (kMaxTapVectors vec4 in shaders/FlipCommon.glsl).
constexpr std::size_t kTapBufferFloats = 4 * ((7 * (2 * kMaxFlipFilterRadius + 1) + 3) / 4);

struct PushConstants {
    int32_t width;
    int32_t height;
    uint32_t referenceImage;
    uint32_t firstCandidate;
    int32_t csfRadius;
    int32_t featureRadius;
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

}  // namespace

Result<FlipPass> FlipPass::create(const Device& device, const DeltaE00Pass::Colormap& colormap) {
    auto colormapBuffer = createColormapBuffer(device, colormap);
    if (!colormapBuffer) return colormapBuffer.error();

    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const VkDescriptorType uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    auto rowFilter = ComputeKernel::create(
        device, kFlipRowFilterSpirv, {storage, storage, uniform, storage}, sizeof(PushConstants));
    if (!rowFilter) return rowFilter.error();
    auto combine = ComputeKernel::create(
        device, kFlipCombineSpirv, {storage, storage, uniform, storage, storage, storage, storage},
        sizeof(PushConstants));
    if (!combine) return combine.error();
    FlipPass pass;
    pass.device_ = &device;
    pass.colormap_ = std::move(colormapBuffer).value();
    pass.rowFilter_ = std::move(rowFilter).value();
    pass.combine_ = std::move(combine).value();
    pass.combine_.bindBuffer(6, pass.colormap_);
    return pass;
}

Status FlipPass::prepare(const FlipBatch& batch, const FlipSettings& settings) {
    if (!(settings.pixelsPerDegree > 0.0) || settings.pixelsPerDegree > 1000.0)
        return Error{"pixels per degree must be in (0, 1000]"};
    if (!taps_.handle() || settings.pixelsPerDegree != tapsPixelsPerDegree_) {
        csf_ = flip::makeCsfKernels(settings.pixelsPerDegree);
        feature_ = flip::makeFeatureKernels(settings.pixelsPerDegree);
        std::vector<float> taps = tapsOf(csf_, feature_);
        taps.resize(kTapBufferFloats, 0.0f);  // the whole uniform block the shaders declare
        auto buffer = Buffer::create(*device_, taps.size() * sizeof(float),
                                     VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::Upload);
        if (!buffer) return buffer.error();
        std::memcpy(buffer->bytes().data(), taps.data(), taps.size() * sizeof(float));
        taps_ = std::move(buffer).value();
        tapsPixelsPerDegree_ = settings.pixelsPerDegree;
    }
    if (std::max(csf_.radius, feature_.radius) > kMaxFlipFilterRadius)
        return Error{"FLIP filters wider than the GPU pass takes"};
    // The reference's planes and each candidate's.
    const VkDeviceSize planeBytes = VkDeviceSize(batch.width) * VkDeviceSize(batch.height) *
                                    (batch.candidateCount + 1) * kPlanesPerImage * sizeof(float);
    if (!planes_.handle() || planes_.size() < planeBytes) {
        auto buffer = Buffer::create(*device_, planeBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     MemoryUse::DeviceLocal);
        if (!buffer) return buffer.error();
        planes_ = std::move(buffer).value();
    }
    return Ok{};
}

Status FlipPass::record(VkCommandBuffer commands, const FlipBatch& batch,
                        const FlipSettings& settings) {
    if (batch.candidateCount == 0 || batch.width <= 0 || batch.height <= 0) return Ok{};
    if (auto prepared = prepare(batch, settings); !prepared) return prepared;
    const PushConstants constants{
        batch.width, batch.height,    batch.referenceImage,           batch.firstCandidate,
        csf_.radius, feature_.radius, float(flip::maxColorDistance())};
    for (const ComputeKernel* kernel : {&rowFilter_, &combine_}) {
        kernel->bindBuffer(0, *batch.reference);
        kernel->bindBuffer(1, *batch.candidates);
        kernel->bindBuffer(2, taps_);
        kernel->bindBuffer(3, planes_);
    }
    combine_.bindBuffer(4, *batch.error);
    combine_.bindBuffer(5, *batch.heatmaps);

    // The row pass: tiles of a row × rows × images.
    rowFilter_.record(commands, &constants,
                      (uint32_t(batch.width) + kWorkgroupSize - 1) / kWorkgroupSize,
                      uint32_t(batch.height), batch.candidateCount + 1);
    computeWriteToComputeReadBarrier(commands);
    // The combination: columns × runs of kCombineRows rows × candidates.
    combine_.record(commands, &constants,
                    (uint32_t(batch.width) + kWorkgroupSize - 1) / kWorkgroupSize,
                    (uint32_t(batch.height) + kCombineRows - 1) / kCombineRows,
                    batch.candidateCount);
    return Ok{};
}

}  // namespace matevo::gpu
