#include "VulkanContext.h"

#include <string>
#include <vector>

#include <GLFW/glfw3.h>

#include "gpu/VulkanError.h"

namespace matevo::editor {
namespace {

// Shown images at once, with room for the ones whose frames are still in flight.
constexpr std::uint32_t kDescriptorSets = 1024;

}  // namespace

Result<std::unique_ptr<VulkanContext>> VulkanContext::create(GLFWwindow* window, bool validation) {
    std::uint32_t glfwCount = 0;
    const char** glfwExtensions = glfwGetRequiredInstanceExtensions(&glfwCount);
    if (!glfwExtensions) return Error{"GLFW found no Vulkan surface support on this display"};
    std::unique_ptr<VulkanContext> context(new VulkanContext());
    auto instance = gpu::InstanceBuilder()
                        .applicationName("matevo editor")
                        .requireExtensions({glfwExtensions, glfwExtensions + glfwCount})
                        .enableValidation(validation)
                        .build();
    if (!instance) return instance.error();
    context->instance_ = std::move(instance).value();

    VkSurfaceKHR surface = VK_NULL_HANDLE;
    if (VkResult result =
            glfwCreateWindowSurface(context->instance_.handle(), window, nullptr, &surface);
        result != VK_SUCCESS)
        return gpu::vulkanError("creating a Vulkan surface for the window", result);
    context->surface_ = UniqueSurface(context->instance_.handle(), surface);

    auto device = gpu::DeviceBuilder(context->instance_)
                      .requireExtensions({VK_KHR_SWAPCHAIN_EXTENSION_NAME})
                      .requirePresentTo(surface)
                      .build();
    if (!device) return device.error();
    context->device_ = std::move(device).value();

    // ImGui's font takes one image; each shown tile two images and the colour map.
    const VkDescriptorPoolSize sizes[] = {
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2 * kDescriptorSets},
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kDescriptorSets}};
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pool.maxSets = kDescriptorSets;
    pool.poolSizeCount = 2;
    pool.pPoolSizes = sizes;
    const VkDevice handle = context->device_.handle();
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    if (VkResult result = vkCreateDescriptorPool(handle, &pool, nullptr, &descriptorPool);
        result != VK_SUCCESS)
        return gpu::vulkanError("creating the descriptor pool", result);
    context->descriptorPool_ = gpu::UniqueDescriptorPool(handle, descriptorPool);

    auto runner = gpu::CommandRunner::create(context->device_);
    if (!runner) return runner.error();
    context->setupRunner_ = std::move(runner).value();
    return context;
}

int VulkanContext::validationMessages() const {
    const gpu::ValidationLog& log = instance_.validationLog();
    return log.errorCount() + log.warningCount();
}

}  // namespace matevo::editor
