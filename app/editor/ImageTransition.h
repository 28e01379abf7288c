#pragma once
// One colour image's layout transition with the access and stage masks on either side.
#include <vulkan/vulkan.h>

namespace matevo::editor {

struct ImageTransition {
    VkImageLayout from;
    VkImageLayout to;
    VkAccessFlags srcAccess;
    VkAccessFlags dstAccess;
    VkPipelineStageFlags srcStage;
    VkPipelineStageFlags dstStage;
};

void recordTransition(VkCommandBuffer commands, VkImage image, const ImageTransition& transition);

}  // namespace matevo::editor
