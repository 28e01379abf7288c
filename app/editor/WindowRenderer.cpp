#include "WindowRenderer.h"

#include <algorithm>
#include <cstring>

#include "VulkanContext.h"
#include "gpu/GpuImage.h"

namespace matevo::editor {
namespace {

VkSurfaceFormatKHR chooseSurfaceFormat(const VulkanContext& context) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(context.physicalDevice(), context.surface(), &count,
                                         nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(context.physicalDevice(), context.surface(), &count,
                                         formats.data());
    // UNORM: ImGui's colours and our sRGB-encoded images are written as they are.
    for (const auto& format : formats)
        if ((format.format == VK_FORMAT_B8G8R8A8_UNORM ||
             format.format == VK_FORMAT_R8G8B8A8_UNORM) &&
            format.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
            return format;
    return formats.at(0);
}

}  // namespace

WindowRenderer::WindowRenderer(const VulkanContext& context, VkExtent2D size)
    : context_(context), device_(context.device()) {
    surfaceFormat_ = chooseSurfaceFormat(context);
    createRenderPass(surfaceFormat_.format);
    for (Frame& frame : frames_) {
        VkCommandPoolCreateInfo pool{};
        pool.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
        pool.queueFamilyIndex = context.queueFamily();
        check(vkCreateCommandPool(device_, &pool, nullptr, &frame.commandPool),
              "vkCreateCommandPool");
        VkCommandBufferAllocateInfo allocate{};
        allocate.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
        allocate.commandPool = frame.commandPool;
        allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocate.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(device_, &allocate, &frame.commands),
              "vkAllocateCommandBuffers");
        VkFenceCreateInfo fence{};
        fence.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
        fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        check(vkCreateFence(device_, &fence, nullptr, &frame.done), "vkCreateFence");
        VkSemaphoreCreateInfo semaphore{};
        semaphore.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
        check(vkCreateSemaphore(device_, &semaphore, nullptr, &frame.imageAcquired),
              "vkCreateSemaphore");
    }
    createSwapchain(size);
}

WindowRenderer::~WindowRenderer() {
    waitIdle();
    destroySwapchain();
    vkDestroySwapchainKHR(device_, swapchain_, nullptr);
    for (Frame& frame : frames_) {
        vkDestroySemaphore(device_, frame.imageAcquired, nullptr);
        vkDestroyFence(device_, frame.done, nullptr);
        vkDestroyCommandPool(device_, frame.commandPool, nullptr);
    }
    vkDestroyRenderPass(device_, renderPass_, nullptr);
}

void WindowRenderer::waitIdle() { check(vkQueueWaitIdle(context_.queue()), "vkQueueWaitIdle"); }

void WindowRenderer::createRenderPass(VkFormat format) {
    VkAttachmentDescription color{};
    color.format = format;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &reference;
    // The acquired image may still be read by presentation until the acquire semaphore fires.
    VkSubpassDependency dependency{};
    dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
    dependency.dstSubpass = 0;
    dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependency.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    VkRenderPassCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
    info.attachmentCount = 1;
    info.pAttachments = &color;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 1;
    info.pDependencies = &dependency;
    check(vkCreateRenderPass(device_, &info, nullptr, &renderPass_), "vkCreateRenderPass");
}

void WindowRenderer::createSwapchain(VkExtent2D size) {
    VkSurfaceCapabilitiesKHR capabilities;
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physicalDevice(), context_.surface(),
                                                    &capabilities),
          "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    extent_ = capabilities.currentExtent.width != UINT32_MAX ? capabilities.currentExtent : size;
    minImageCount_ = capabilities.minImageCount + 1;
    if (capabilities.maxImageCount > 0)
        minImageCount_ = std::min(minImageCount_, capabilities.maxImageCount);

    VkSwapchainCreateInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
    info.surface = context_.surface();
    info.minImageCount = minImageCount_;
    info.imageFormat = surfaceFormat_.format;
    info.imageColorSpace = surfaceFormat_.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    // TRANSFER_SRC lets F12 copy the frame back for a snapshot.
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                      (capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = capabilities.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always available; no tearing
    info.clipped = VK_TRUE;
    info.oldSwapchain = swapchain_;
    VkSwapchainKHR created = VK_NULL_HANDLE;
    check(vkCreateSwapchainKHR(device_, &info, nullptr, &created), "vkCreateSwapchainKHR");
    vkDestroySwapchainKHR(device_, swapchain_, nullptr);
    swapchain_ = created;

    std::uint32_t count = 0;
    vkGetSwapchainImagesKHR(device_, swapchain_, &count, nullptr);
    images_.resize(count);
    vkGetSwapchainImagesKHR(device_, swapchain_, &count, images_.data());
    for (VkImage image : images_) {
        VkImageViewCreateInfo view{};
        view.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
        view.image = image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = surfaceFormat_.format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        check(vkCreateImageView(device_, &view, nullptr, &views_.emplace_back()),
              "vkCreateImageView");
        VkFramebufferCreateInfo framebuffer{};
        framebuffer.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
        framebuffer.renderPass = renderPass_;
        framebuffer.attachmentCount = 1;
        framebuffer.pAttachments = &views_.back();
        framebuffer.width = extent_.width;
        framebuffer.height = extent_.height;
        framebuffer.layers = 1;
        check(vkCreateFramebuffer(device_, &framebuffer, nullptr, &framebuffers_.emplace_back()),
              "vkCreateFramebuffer");
        VkSemaphoreCreateInfo semaphore{};
        semaphore.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
        check(vkCreateSemaphore(device_, &semaphore, nullptr, &renderDone_.emplace_back()),
              "vkCreateSemaphore");
    }
    needsRebuild_ = false;
}

void WindowRenderer::destroySwapchain() {
    for (VkFramebuffer framebuffer : framebuffers_)
        vkDestroyFramebuffer(device_, framebuffer, nullptr);
    for (VkImageView view : views_) vkDestroyImageView(device_, view, nullptr);
    for (VkSemaphore semaphore : renderDone_) vkDestroySemaphore(device_, semaphore, nullptr);
    framebuffers_.clear();
    views_.clear();
    renderDone_.clear();
    images_.clear();
}

bool WindowRenderer::drawFrame(VkExtent2D size, const FrameRecording& recording,
                               Rgba8Image* capture) {
    if (needsRebuild_ || size.width != extent_.width || size.height != extent_.height) {
        waitIdle();
        destroySwapchain();
        createSwapchain(size);
    }
    Frame& frame = frames_[frameIndex_];
    check(vkWaitForFences(device_, 1, &frame.done, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    std::uint32_t imageIndex = 0;
    const VkResult acquired = vkAcquireNextImageKHR(
        device_, swapchain_, UINT64_MAX, frame.imageAcquired, VK_NULL_HANDLE, &imageIndex);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        needsRebuild_ = true;
        return false;
    }
    if (acquired != VK_SUBOPTIMAL_KHR) check(acquired, "vkAcquireNextImageKHR");
    check(vkResetFences(device_, 1, &frame.done), "vkResetFences");
    check(vkResetCommandPool(device_, frame.commandPool, 0), "vkResetCommandPool");

    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(frame.commands, &begin), "vkBeginCommandBuffer");
    if (recording.beforePass) recording.beforePass(frame.commands);
    VkClearValue clear{};
    clear.color = {{0.09f, 0.09f, 0.10f, 1.0f}};
    VkRenderPassBeginInfo pass{};
    pass.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    pass.renderPass = renderPass_;
    pass.framebuffer = framebuffers_[imageIndex];
    pass.renderArea.extent = extent_;
    pass.clearValueCount = 1;
    pass.pClearValues = &clear;
    vkCmdBeginRenderPass(frame.commands, &pass, VK_SUBPASS_CONTENTS_INLINE);
    if (recording.inPass) recording.inPass(frame.commands);
    vkCmdEndRenderPass(frame.commands);
    if (capture) recordCapture(frame.commands, imageIndex);
    check(vkEndCommandBuffer(frame.commands), "vkEndCommandBuffer");

    const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &frame.imageAcquired;
    submit.pWaitDstStageMask = &waitStage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &frame.commands;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &renderDone_[imageIndex];
    check(vkQueueSubmit(context_.queue(), 1, &submit, frame.done), "vkQueueSubmit");

    VkPresentInfoKHR present{};
    present.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &renderDone_[imageIndex];
    present.swapchainCount = 1;
    present.pSwapchains = &swapchain_;
    present.pImageIndices = &imageIndex;
    const VkResult presented = vkQueuePresentKHR(context_.queue(), &present);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR ||
        acquired == VK_SUBOPTIMAL_KHR)
        needsRebuild_ = true;
    else
        check(presented, "vkQueuePresentKHR");

    if (capture) finishCapture(frame, *capture);
    frameIndex_ = (frameIndex_ + 1) % kFramesInFlight;
    return true;
}

void WindowRenderer::recordCapture(VkCommandBuffer commands, std::uint32_t imageIndex) {
    const VkDeviceSize bytes = VkDeviceSize(extent_.width) * extent_.height * 4;
    if (!readback_ || readback_->size() < bytes)
        readback_ = std::make_unique<HostBuffer>(context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    VkImage image = images_[imageIndex];
    gpu::transitionImage(commands, image, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                         VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent_.width, extent_.height, 1};
    vkCmdCopyImageToBuffer(commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback_->buffer(), 1, &region);
    gpu::transitionImage(commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
    VkBufferMemoryBarrier toHost{};
    toHost.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = readback_->buffer();
    toHost.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0,
                         nullptr, 1, &toHost, 0, nullptr);
}

void WindowRenderer::finishCapture(const Frame& frame, Rgba8Image& capture) {
    check(vkWaitForFences(device_, 1, &frame.done, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    capture.width = int(extent_.width);
    capture.height = int(extent_.height);
    capture.rgba.resize(std::size_t(extent_.width) * extent_.height * 4);
    std::memcpy(capture.rgba.data(), readback_->data(), capture.rgba.size());
    const bool bgra = surfaceFormat_.format == VK_FORMAT_B8G8R8A8_UNORM ||
                      surfaceFormat_.format == VK_FORMAT_B8G8R8A8_SRGB;
    for (std::size_t i = 0; i < capture.rgba.size(); i += 4) {
        if (bgra) std::swap(capture.rgba[i], capture.rgba[i + 2]);
        capture.rgba[i + 3] = 255;  // the window is opaque
    }
}

}  // namespace matevo::editor
