#include "gpu/DeltaE00Pass.h"

#include <shaders/kDeltaE00Spirv.h>

namespace matevo::gpu {
namespace {

constexpr uint32_t kWorkgroupSize = 64;  // local_size_x in the shader

struct PushConstants {
    uint32_t pixelCount;
    uint32_t referenceImage;
    uint32_t firstCandidate;
};

}  // namespace

Result<DeltaE00Pass> DeltaE00Pass::create(const Device& device) {
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    auto kernel = ComputeKernel::create(device, kDeltaE00Spirv, {storage, storage, storage},
                                        sizeof(PushConstants));
    if (!kernel) return kernel.error();
    DeltaE00Pass pass;
    pass.kernel_ = std::move(kernel).value();
    return pass;
}

void DeltaE00Pass::record(VkCommandBuffer commands, const DeltaE00Batch& batch) const {
    kernel_.bindBuffer(0, *batch.reference);
    kernel_.bindBuffer(1, *batch.candidates);
    kernel_.bindBuffer(2, *batch.deltaE);
    const PushConstants constants{batch.pixelCount, batch.referenceImage, batch.firstCandidate};
    kernel_.record(commands, &constants, (batch.pixelCount + kWorkgroupSize - 1) / kWorkgroupSize,
                   batch.candidateCount, 1);
}

}  // namespace matevo::gpu
