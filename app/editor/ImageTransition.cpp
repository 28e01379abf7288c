#include "ImageTransition.h"

namespace matevo::editor {

void recordTransition(VkCommandBuffer commands, VkImage image, const ImageTransition& transition) {
    VkImageMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    barrier.srcAccessMask = transition.srcAccess;
    barrier.dstAccessMask = transition.dstAccess;
    barrier.oldLayout = transition.from;
    barrier.newLayout = transition.to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(commands, transition.srcStage, transition.dstStage, 0, 0, nullptr, 0,
                         nullptr, 1, &barrier);
}

}  // namespace matevo::editor
