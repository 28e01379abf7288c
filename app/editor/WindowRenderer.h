#pragma once
// The window's swapchain, render pass and frames in flight. An out-of-date or suboptimal
// swapchain (resize, minimise) is normal control flow: the frame is skipped and the swapchain
// rebuilt before the next one. Can copy a finished frame back to memory for snapshots.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "HostBuffer.h"
#include "Rgba8Image.h"

namespace matevo::editor {

class VulkanContext;

struct FrameRecording {
    std::function<void(VkCommandBuffer)> beforePass;  // uploads
    std::function<void(VkCommandBuffer)> inPass;      // ImGui draws
};

class WindowRenderer {
public:
    WindowRenderer(const VulkanContext& context, VkExtent2D size);
    ~WindowRenderer();
    WindowRenderer(const WindowRenderer&) = delete;
    WindowRenderer& operator=(const WindowRenderer&) = delete;

    VkRenderPass renderPass() const { return renderPass_; }
    std::uint32_t minImageCount() const { return minImageCount_; }
    std::uint32_t imageCount() const { return std::uint32_t(images_.size()); }

    // Draws and presents one frame at the window's framebuffer size. Returns false when the
    // frame was skipped because the swapchain had to be rebuilt. With `capture`, the frame is
    // also read back (this waits for it to finish).
    bool drawFrame(VkExtent2D size, const FrameRecording& recording, Rgba8Image* capture = nullptr);
    // Waits until no frame is in flight, so resources they use may be changed.
    void waitIdle();

private:
    struct Frame {
        VkCommandPool commandPool = VK_NULL_HANDLE;
        VkCommandBuffer commands = VK_NULL_HANDLE;
        VkFence done = VK_NULL_HANDLE;
        VkSemaphore imageAcquired = VK_NULL_HANDLE;
    };
    static constexpr std::size_t kFramesInFlight = 2;

    void createRenderPass(VkFormat format);
    void createSwapchain(VkExtent2D size);
    void destroySwapchain();
    void recordCapture(VkCommandBuffer commands, std::uint32_t imageIndex);
    void finishCapture(const Frame& frame, Rgba8Image& capture);

    const VulkanContext& context_;
    VkDevice device_;
    VkSurfaceFormatKHR surfaceFormat_{};
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkExtent2D extent_{};
    std::uint32_t minImageCount_ = 2;
    bool needsRebuild_ = false;
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    std::vector<VkFramebuffer> framebuffers_;
    std::vector<VkSemaphore> renderDone_;  // per swapchain image: presentation waits on it
    std::array<Frame, kFramesInFlight> frames_{};
    std::size_t frameIndex_ = 0;
    std::unique_ptr<HostBuffer> readback_;
};

}  // namespace matevo::editor
