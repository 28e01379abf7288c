#include "gpu/DeltaE00Pass.h"

#include <cstring>

#include <shaders/kDeltaE00HeatmapSpirv.h>

namespace matevo::gpu {
namespace {

constexpr uint32_t kWorkgroupSize = 64;  // local_size_x in the shader

struct PushConstants {
    uint32_t pixelCount;
    uint32_t referenceImage;
    uint32_t firstCandidate;
    float minDeltaE;
    float maxDeltaE;
};

}  // namespace

Result<Buffer> createColormapBuffer(const Device& device, const DeltaE00Pass::Colormap& colormap) {
    auto buffer = Buffer::create(device, sizeof(colormap), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                 MemoryUse::Upload);
    if (!buffer) return buffer.error();
    std::memcpy(buffer->bytes().data(), colormap.data(), sizeof(colormap));
    return buffer;
}

Result<DeltaE00Pass> DeltaE00Pass::create(const Device& device, const Colormap& colormap) {
    auto colormapBuffer = createColormapBuffer(device, colormap);
    if (!colormapBuffer) return colormapBuffer.error();

    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    auto kernel = ComputeKernel::create(device, kDeltaE00HeatmapSpirv,
                                        {storage, storage, storage, storage, storage},
                                        sizeof(PushConstants));
    if (!kernel) return kernel.error();
    DeltaE00Pass pass;
    pass.colormap_ = std::move(colormapBuffer).value();
    pass.kernel_ = std::move(kernel).value();
    pass.kernel_.bindBuffer(4, pass.colormap_);
    return pass;
}

void DeltaE00Pass::record(VkCommandBuffer commands, const DeltaE00Batch& batch) const {
    kernel_.bindBuffer(0, *batch.reference);
    kernel_.bindBuffer(1, *batch.candidates);
    kernel_.bindBuffer(2, *batch.deltaE);
    kernel_.bindBuffer(3, *batch.heatmaps);
    const PushConstants constants{batch.pixelCount, batch.referenceImage, batch.firstCandidate,
                                  batch.minDeltaE, batch.maxDeltaE};
    kernel_.record(commands, &constants, (batch.pixelCount + kWorkgroupSize - 1) / kWorkgroupSize,
                   batch.candidateCount, 1);
}

}  // namespace matevo::gpu
