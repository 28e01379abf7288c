#include "VulkanContext.h"

#include <string>
#include <vector>

#include <GLFW/glfw3.h>

#include "gpu/VulkanError.h"
#include "gpu/VulkanObjects.h"

namespace matevo::editor {
namespace {

// Shown images at once, with room for the ones whose frames are still in flight.
constexpr std::uint32_t kDescriptorSets = 1024;

}  // namespace

Result<std::unique_ptr<VulkanContext>> VulkanContext::create(GLFWwindow* window, bool validation) {
    std::uint32_t glfwCount = 0;
    const char** glfwExtensions = glfwGetRequiredInstanceExtensions(&glfwCount);
    if (!glfwExtensions)
        return environmentError("GLFW found no Vulkan surface support on this display");
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
    // Each shown image frees its own set when it goes (ShownImage).
    auto descriptorPool =
        gpu::createDescriptorPool(context->device_.handle(), kDescriptorSets, sizes,
                                  VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT);
    if (!descriptorPool) return descriptorPool.error();
    context->descriptorPool_ = std::move(descriptorPool).value();

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
