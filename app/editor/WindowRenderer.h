#pragma once
// The window's swapchain, render pass and frames in flight. An out-of-date or suboptimal
// swapchain (resize, minimise) is normal control flow: the frame is skipped and the swapchain
// rebuilt before the next one. Can copy a finished frame back to memory for snapshots. Every
// handle is owned by a core/gpu RAII type; Vulkan failures come back as errors.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "PictureHistory.h"
#include "PixelArea.h"
#include "Rgba8Image.h"
#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/VulkanHandle.h"

namespace matevo::editor {

class VulkanContext;

struct FrameRecording {
    // Records the frame's draws inside the render pass, within `areas` only (disjoint, already
    // cleared; the pixels outside them hold this frame's picture). `frameSlot` (below
    // kFramesInFlight) names the frame: what it uses must live until that slot is drawn again.
    std::function<void(VkCommandBuffer commands, std::size_t frameSlot,
                       std::span<const ui::PixelArea> areas)>
        inPass;
    // The pixels whose picture differs from the last frame drawn, as disjoint rectangles;
    // nullopt: possibly all.
    std::optional<std::vector<ui::PixelArea>> changed;
};

class WindowRenderer {
public:
    static constexpr std::size_t kFramesInFlight = 2;

    static Result<std::unique_ptr<WindowRenderer>> create(const VulkanContext& context,
                                                          VkExtent2D size);
    ~WindowRenderer();  // waits for the frames in flight
    WindowRenderer(const WindowRenderer&) = delete;
    WindowRenderer& operator=(const WindowRenderer&) = delete;

    VkRenderPass renderPass() const { return renderPass_.get(); }
    std::uint32_t minImageCount() const { return minImageCount_; }
    std::uint32_t imageCount() const { return std::uint32_t(images_.size()); }

    // Draws and presents one frame at the window's framebuffer size. A swapchain image keeps
    // the picture it was last drawn with, so only the pixels changed since then are drawn
    // again (on lavapipe the window's pixels are most of a frame's cost). false when the frame
    // was skipped because the swapchain had to be rebuilt. With `capture`, the frame is also
    // read back (this waits for it to finish).
    Result<bool> drawFrame(VkExtent2D size, const FrameRecording& recording,
                           Rgba8Image* capture = nullptr);
    // The next frames draw every swapchain image whole (its contents are no longer trusted).
    void forgetPictures();
    // Waits until no frame is in flight (before releasing what frames use, at shutdown).
    Status waitIdle();

private:
    using UniqueSwapchain = gpu::OwnedHandle<VkDevice, VkSwapchainKHR, vkDestroySwapchainKHR>;
    struct Frame {
        gpu::UniqueCommandPool commandPool;
        VkCommandBuffer commands = VK_NULL_HANDLE;  // freed with the pool
        gpu::UniqueFence done;
        gpu::UniqueSemaphore imageAcquired;
    };
    struct SwapchainImage {
        VkImage image = VK_NULL_HANDLE;  // owned by the swapchain
        gpu::UniqueImageView view;
        gpu::UniqueFramebuffer framebuffer;
        gpu::UniqueSemaphore renderDone;  // presentation waits on it
    };

    explicit WindowRenderer(const VulkanContext& context) : context_(context) {}
    Status createRenderPasses();
    Status createFrames();
    Status createSwapchain(VkExtent2D size);
    Status recordCapture(VkCommandBuffer commands, std::uint32_t imageIndex);
    void finishCapture(Rgba8Image& capture) const;

    const VulkanContext& context_;
    VkDevice device_ = VK_NULL_HANDLE;
    VkSurfaceFormatKHR surfaceFormat_{};
    gpu::UniqueRenderPass renderPass_;  // clears the whole image first
    gpu::UniqueRenderPass redrawPass_;  // keeps what the image holds (compatible with the above)
    std::array<Frame, kFramesInFlight> frames_;
    std::size_t frameIndex_ = 0;
    UniqueSwapchain swapchain_;
    VkExtent2D extent_{};
    std::uint32_t minImageCount_ = 2;
    bool needsRebuild_ = false;
    ui::PictureHistory pictures_;         // what each swapchain image shows
    std::vector<SwapchainImage> images_;  // after the swapchain: released before it
    std::optional<gpu::Buffer> readback_;
};

}  // namespace matevo::editor
