#include "WindowRenderer.h"

#include <algorithm>
#include <cstring>

#include "VulkanContext.h"
#include "gpu/GpuImage.h"
#include "gpu/VulkanError.h"
#include "gpu/VulkanObjects.h"

namespace matevo::editor {
namespace {

VkSurfaceFormatKHR chooseSurfaceFormat(const VulkanContext& context) {
    const VkPhysicalDevice physicalDevice = context.device().physicalDevice();
    std::uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice, context.surface(), &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice, context.surface(), &count, formats.data());
    // UNORM: ImGui's colours and our sRGB-encoded images are written as they are.
    for (const auto& format : formats)
        if ((format.format == VK_FORMAT_B8G8R8A8_UNORM ||
             format.format == VK_FORMAT_R8G8B8A8_UNORM) &&
            format.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
            return format;
    return formats.empty() ? VkSurfaceFormatKHR{} : formats.front();
}

}  // namespace

Result<std::unique_ptr<WindowRenderer>> WindowRenderer::create(const VulkanContext& context,
                                                               VkExtent2D size) {
    std::unique_ptr<WindowRenderer> renderer(new WindowRenderer(context));
    renderer->device_ = context.device().handle();
    renderer->surfaceFormat_ = chooseSurfaceFormat(context);
    if (renderer->surfaceFormat_.format == VK_FORMAT_UNDEFINED)
        return environmentError("the window's surface offers no image format");
    if (Status s = renderer->createRenderPasses(); !s) return s.error();
    if (Status s = renderer->createFrames(); !s) return s.error();
    if (Status s = renderer->createSwapchain(size); !s) return s.error();
    return renderer;
}

WindowRenderer::~WindowRenderer() {
    // Nothing to report a failure to at teardown; the handles are released either way.
    (void)waitIdle();
}

void WindowRenderer::forgetPictures() { pictures_.forget(); }

Status WindowRenderer::waitIdle() {
    const auto queueLock = context_.device().lockQueue();
    return gpu::checkVulkan(vkQueueWaitIdle(context_.device().queue()), "waiting for the queue");
}

Status WindowRenderer::createRenderPasses() {
    for (bool keep : {false, true}) {
        VkAttachmentDescription color{};
        color.format = surfaceFormat_.format;
        color.samples = VK_SAMPLE_COUNT_1_BIT;
        color.loadOp = keep ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
        color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        color.initialLayout = keep ? VK_IMAGE_LAYOUT_PRESENT_SRC_KHR : VK_IMAGE_LAYOUT_UNDEFINED;
        color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
        VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        VkSubpassDescription subpass{};
        subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        subpass.colorAttachmentCount = 1;
        subpass.pColorAttachments = &reference;
        // The acquired image may still be read by presentation until the acquire semaphore
        // fires. The same dependency in both passes: pipelines need compatible passes.
        VkSubpassDependency dependency{};
        dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
        dependency.dstSubpass = 0;
        dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
        dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
        dependency.dstAccessMask =
            VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        auto renderPass = gpu::createRenderPass(device_, std::span(&color, 1), subpass,
                                                std::span(&dependency, 1));
        if (!renderPass) return renderPass.error();
        (keep ? redrawPass_ : renderPass_) = std::move(renderPass).value();
    }
    return Ok{};
}

Status WindowRenderer::createFrames() {
    for (Frame& frame : frames_) {
        auto commandPool = gpu::createCommandPool(device_, context_.device().queueFamily());
        if (!commandPool) return commandPool.error();
        frame.commandPool = std::move(commandPool).value();
        auto commands = gpu::allocateCommandBuffer(device_, frame.commandPool.get());
        if (!commands) return commands.error();
        frame.commands = *commands;
        // Signalled: the first wait for a frame slot has no earlier frame to wait for.
        auto done = gpu::createFence(device_, true);
        if (!done) return done.error();
        frame.done = std::move(done).value();
        auto acquired = gpu::createSemaphore(device_);
        if (!acquired) return acquired.error();
        frame.imageAcquired = std::move(acquired).value();
    }
    return Ok{};
}

Status WindowRenderer::createSwapchain(VkExtent2D size) {
    const VkPhysicalDevice physicalDevice = context_.device().physicalDevice();
    VkSurfaceCapabilitiesKHR capabilities;
    if (Status s = gpu::checkVulkan(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(
                                        physicalDevice, context_.surface(), &capabilities),
                                    "reading the surface's capabilities");
        !s)
        return s;
    extent_ = capabilities.currentExtent.width != UINT32_MAX ? capabilities.currentExtent : size;
    minImageCount_ = capabilities.minImageCount + 1;
    if (capabilities.maxImageCount > 0)
        minImageCount_ = std::min(minImageCount_, capabilities.maxImageCount);

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
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
    // Whole images: a frame redraws only what changed and keeps the rest, obscured or not.
    info.clipped = VK_FALSE;
    info.oldSwapchain = swapchain_.get();
    VkSwapchainKHR created = VK_NULL_HANDLE;
    if (Status s = gpu::checkVulkan(vkCreateSwapchainKHR(device_, &info, nullptr, &created),
                                    "creating the swapchain");
        !s)
        return s;
    images_.clear();  // the old swapchain's views and framebuffers, before the swapchain
    swapchain_ = UniqueSwapchain(device_, created);

    std::uint32_t count = 0;
    vkGetSwapchainImagesKHR(device_, created, &count, nullptr);
    std::vector<VkImage> images(count);
    vkGetSwapchainImagesKHR(device_, created, &count, images.data());
    for (VkImage image : images) {
        SwapchainImage& target = images_.emplace_back();
        target.image = image;
        auto view =
            gpu::createImageView(device_, image, VK_IMAGE_VIEW_TYPE_2D, surfaceFormat_.format);
        if (!view) return view.error();
        target.view = std::move(view).value();
        const VkImageView imageView = target.view.get();
        auto framebuffer = gpu::createFramebuffer(
            device_, renderPass_.get(), std::span(&imageView, 1), extent_.width, extent_.height);
        if (!framebuffer) return framebuffer.error();
        target.framebuffer = std::move(framebuffer).value();
        auto renderDone = gpu::createSemaphore(device_);
        if (!renderDone) return renderDone.error();
        target.renderDone = std::move(renderDone).value();
    }
    pictures_.reset(images_.size(), {0, 0, int(extent_.width), int(extent_.height)});
    needsRebuild_ = false;
    return Ok{};
}

Result<bool> WindowRenderer::drawFrame(VkExtent2D size, const FrameRecording& recording,
                                       Rgba8Image* capture) {
    if (needsRebuild_ || size.width != extent_.width || size.height != extent_.height) {
        if (Status s = waitIdle(); !s) return s.error();
        if (Status s = createSwapchain(size); !s) return s.error();
    }
    Frame& frame = frames_[frameIndex_];
    VkFence done = frame.done.get();
    if (Status s = gpu::checkVulkan(vkWaitForFences(device_, 1, &done, VK_TRUE, UINT64_MAX),
                                    "waiting for a frame");
        !s)
        return s.error();
    std::uint32_t imageIndex = 0;
    const VkResult acquired =
        vkAcquireNextImageKHR(device_, swapchain_.get(), UINT64_MAX, frame.imageAcquired.get(),
                              VK_NULL_HANDLE, &imageIndex);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        needsRebuild_ = true;
        return false;
    }
    if (acquired != VK_SUBOPTIMAL_KHR)
        if (Status s = gpu::checkVulkan(acquired, "acquiring a swapchain image"); !s)
            return s.error();
    vkResetFences(device_, 1, &done);
    vkResetCommandPool(device_, frame.commandPool.get(), 0);

    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (Status s =
            gpu::checkVulkan(vkBeginCommandBuffer(frame.commands, &begin), "recording a frame");
        !s)
        return s.error();
    SwapchainImage& target = images_[imageIndex];
    const std::vector<ui::PixelArea> areas = pictures_.areasToDraw(imageIndex, recording.changed);
    const bool whole = areas.size() == 1 &&
                       areas[0] == ui::PixelArea{0, 0, int(extent_.width), int(extent_.height)};
    VkClearValue clear{};
    clear.color = {{0.09f, 0.09f, 0.10f, 1.0f}};
    VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    pass.renderPass = whole ? renderPass_.get() : redrawPass_.get();
    pass.framebuffer = target.framebuffer.get();
    pass.renderArea.extent = extent_;
    pass.clearValueCount = whole ? 1 : 0;
    pass.pClearValues = &clear;
    vkCmdBeginRenderPass(frame.commands, &pass, VK_SUBPASS_CONTENTS_INLINE);
    if (!whole && !areas.empty()) {
        const VkClearAttachment attachment{VK_IMAGE_ASPECT_COLOR_BIT, 0, clear};
        std::vector<VkClearRect> rects;
        for (const ui::PixelArea& area : areas)
            rects.push_back({{{area.x0, area.y0},
                              {std::uint32_t(area.x1 - area.x0), std::uint32_t(area.y1 - area.y0)}},
                             0,
                             1});
        vkCmdClearAttachments(frame.commands, 1, &attachment, std::uint32_t(rects.size()),
                              rects.data());
    }
    if (recording.inPass) recording.inPass(frame.commands, frameIndex_, areas);
    vkCmdEndRenderPass(frame.commands);
    if (capture)
        if (Status s = recordCapture(frame.commands, imageIndex); !s) return s.error();
    if (Status s = gpu::checkVulkan(vkEndCommandBuffer(frame.commands), "recording a frame"); !s)
        return s.error();

    const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    const VkSemaphore imageAcquired = frame.imageAcquired.get();
    const VkSemaphore renderDone = images_[imageIndex].renderDone.get();
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &imageAcquired;
    submit.pWaitDstStageMask = &waitStage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &frame.commands;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &renderDone;
    VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &renderDone;
    present.swapchainCount = 1;
    const VkSwapchainKHR swapchain = swapchain_.get();
    present.pSwapchains = &swapchain;
    present.pImageIndices = &imageIndex;
    VkResult presented = VK_SUCCESS;
    {
        const auto queueLock = context_.device().lockQueue();
        if (Status s = gpu::checkVulkan(vkQueueSubmit(context_.device().queue(), 1, &submit, done),
                                        "submitting a frame");
            !s)
            return s.error();
        presented = vkQueuePresentKHR(context_.device().queue(), &present);
    }
    pictures_.drawn(imageIndex, recording.changed);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR ||
        acquired == VK_SUBOPTIMAL_KHR)
        needsRebuild_ = true;
    else if (Status s = gpu::checkVulkan(presented, "presenting a frame"); !s)
        return s.error();

    if (capture) {
        if (Status s = gpu::checkVulkan(vkWaitForFences(device_, 1, &done, VK_TRUE, UINT64_MAX),
                                        "waiting for a frame");
            !s)
            return s.error();
        finishCapture(*capture);
    }
    frameIndex_ = (frameIndex_ + 1) % kFramesInFlight;
    return true;
}

Status WindowRenderer::recordCapture(VkCommandBuffer commands, std::uint32_t imageIndex) {
    const VkDeviceSize bytes = VkDeviceSize(extent_.width) * extent_.height * 4;
    if (!readback_ || readback_->size() < bytes) {
        auto buffer = gpu::Buffer::create(
            context_.device(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback);
        if (!buffer) return buffer.error();
        readback_ = std::move(buffer).value();
    }
    VkImage image = images_[imageIndex].image;
    gpu::transitionImage(
        commands, image, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
        VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent_.width, extent_.height, 1};
    vkCmdCopyImageToBuffer(commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback_->handle(), 1, &region);
    gpu::transitionImage(commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
    VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = readback_->handle();
    toHost.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0,
                         nullptr, 1, &toHost, 0, nullptr);
    return Ok{};
}

void WindowRenderer::finishCapture(Rgba8Image& capture) const {
    capture.width = int(extent_.width);
    capture.height = int(extent_.height);
    capture.rgba.resize(std::size_t(extent_.width) * extent_.height * 4);
    std::memcpy(capture.rgba.data(), readback_->bytes().data(), capture.rgba.size());
    const bool bgra = surfaceFormat_.format == VK_FORMAT_B8G8R8A8_UNORM ||
                      surfaceFormat_.format == VK_FORMAT_B8G8R8A8_SRGB;
    for (std::size_t i = 0; i < capture.rgba.size(); i += 4) {
        if (bgra) std::swap(capture.rgba[i], capture.rgba[i + 2]);
        capture.rgba[i + 3] = 255;  // the window is opaque
    }
}

}  // namespace matevo::editor
