#pragma once
// One reusable command buffer and a fence: record, submit, wait. Each batch of work is one
// submission, so results are ready (and buffers reusable) when submitAndWait returns. Runners
// on several threads may share a device: each submission holds the device's queue lock.
#include "common/Result.h"
#include "gpu/Device.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

class CommandRunner {
public:
    static Result<CommandRunner> create(const Device& device);

    // Resets the command buffer and starts recording into it.
    Result<VkCommandBuffer> begin();
    Status submitAndWait();

private:
    const Device* device_ = nullptr;  // outlives the runner
    UniqueCommandPool pool_;
    UniqueFence fence_;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;  // freed with the pool
};

// Global barriers between passes of one submission.
void computeWriteToComputeReadBarrier(VkCommandBuffer commands);
void computeWriteToHostReadBarrier(VkCommandBuffer commands);

}  // namespace matevo::gpu
