#include "gpu/CommandRunner.h"

#include <cstdint>

#include "gpu/VulkanError.h"
#include "gpu/VulkanObjects.h"

namespace matevo::gpu {
namespace {

void memoryBarrier(VkCommandBuffer commands, VkPipelineStageFlags destinationStage,
                   VkAccessFlags destinationAccess) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = destinationAccess;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, destinationStage, 0, 1,
                         &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace

Result<CommandRunner> CommandRunner::create(const Device& device) {
    CommandRunner runner;
    runner.device_ = &device;

    auto pool = createCommandPool(device.handle(), device.queueFamily(),
                                  VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT);
    if (!pool) return pool.error();
    runner.pool_ = std::move(pool).value();
    auto commands = allocateCommandBuffer(device.handle(), runner.pool_.get());
    if (!commands) return commands.error();
    runner.commands_ = *commands;
    auto fence = createFence(device.handle());
    if (!fence) return fence.error();
    runner.fence_ = std::move(fence).value();
    return runner;
}

Result<VkCommandBuffer> CommandRunner::begin() {
    vkResetCommandBuffer(commands_, 0);
    VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (VkResult result = vkBeginCommandBuffer(commands_, &beginInfo); result != VK_SUCCESS)
        return vulkanError("beginning a command buffer", result);
    return commands_;
}

Status CommandRunner::submitAndWait() {
    if (VkResult result = vkEndCommandBuffer(commands_); result != VK_SUCCESS)
        return vulkanError("recording commands", result);
    VkSubmitInfo submitInfo{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submitInfo.commandBufferCount = 1;
    submitInfo.pCommandBuffers = &commands_;
    VkFence fence = fence_.get();
    {
        const auto queueLock = device_->lockQueue();
        if (VkResult result = vkQueueSubmit(device_->queue(), 1, &submitInfo, fence);
            result != VK_SUCCESS)
            return vulkanError("submitting commands", result);
    }
    VkResult waited = vkWaitForFences(device_->handle(), 1, &fence, VK_TRUE, UINT64_MAX);
    vkResetFences(device_->handle(), 1, &fence);
    if (waited != VK_SUCCESS) return vulkanError("waiting for the GPU", waited);
    return Ok{};
}

void computeWriteToComputeReadBarrier(VkCommandBuffer commands) {
    memoryBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
}

void computeWriteToHostReadBarrier(VkCommandBuffer commands) {
    memoryBarrier(commands, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

}  // namespace matevo::gpu
