#pragma once
// Shows our own images in Dear ImGui 1.86, whose Vulkan backend binds only its font texture.
// Images are DisplayTiles on the window's device (the worker renders into them, nothing is
// copied for display). The UI draws them with ordinary ImGui calls whose ImTextureID comes from
// a ShownImage; before the backend renders, prepare() turns each such draw command into a
// callback that binds our pipeline (same vertex layout and transform as ImGui's) with the
// image's descriptor set and draws the command's own vertices, then resets ImGui's state.
// Used on the UI thread only.
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <imgui.h>
#include <vulkan/vulkan.h>

#include "WindowRenderer.h"
#include "color/ImageMetric.h"
#include "common/Image.h"
#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/DisplayTile.h"
#include "gpu/VulkanHandle.h"

namespace matevo::editor {

class VulkanContext;

// A tile made drawable: its descriptor set, and the ImGui ids that draw its render or its ΔE00
// map as a heatmap. Whoever shows the ids holds it; frames in flight hold it too, so it (and
// its tile) is released only when no frame uses it any more.
class ShownImage : public std::enable_shared_from_this<ShownImage> {
public:
    ~ShownImage();
    ShownImage(const ShownImage&) = delete;
    ShownImage& operator=(const ShownImage&) = delete;

    ImTextureID render() { return &views_[0]; }
    // Null when the tile has no ΔE00 map (e.g. the target).
    ImTextureID heatmap() { return tile_->deltaE ? &views_[1] : nullptr; }
    const gpu::DisplayTile& tile() const { return *tile_; }

private:
    friend class ImageBridge;
    struct View {
        ShownImage* owner;
        bool heatmap;
    };
    ShownImage(std::shared_ptr<const gpu::DisplayTile> tile, VkDevice device, VkDescriptorPool pool,
               VkDescriptorSet set);

    std::shared_ptr<const gpu::DisplayTile> tile_;
    VkDevice device_;
    VkDescriptorPool pool_;
    VkDescriptorSet set_;
    std::array<View, 2> views_;
};

class ImageBridge {
public:
    static Result<std::unique_ptr<ImageBridge>> create(VulkanContext& context,
                                                       VkRenderPass renderPass);

    Result<std::shared_ptr<ShownImage>> show(std::shared_ptr<const gpu::DisplayTile> tile);
    // Host pictures (e.g. Compare metrics' renders) copied into tiles and shown; waits for the
    // upload.
    Result<std::vector<std::shared_ptr<ShownImage>>> upload(std::span<const Image> images);
    // How error maps are coloured from the next frame on: ΔE00 through viridis over
    // [minDeltaE, maxDeltaE], or ꟻLIP through magma over [0, 1].
    void setHeatmap(ImageMetric metric, float minDeltaE, float maxDeltaE);

    // Rewrites `drawData` so our images draw through our pipeline into `commands`, and keeps
    // what they use alive until frame slot `frameSlot` is drawn again.
    void prepare(ImDrawData& drawData, VkCommandBuffer commands, std::size_t frameSlot);

private:
    struct ImageDraw {
        ImageBridge* bridge;
        const ShownImage::View* view;
        ImVec4 clipRect;
        unsigned elementCount;
        unsigned firstIndex;
        int vertexOffset;
    };
    explicit ImageBridge(VulkanContext& context) : context_(context) {}
    Status createLayouts();
    Status createPipeline(VkRenderPass renderPass);
    Status createSharedResources();
    static void drawCallback(const ImDrawList* list, const ImDrawCmd* command);
    void draw(const ImageDraw& image) const;

    VulkanContext& context_;
    VkDevice device_ = VK_NULL_HANDLE;
    gpu::UniqueSampler renderSampler_;  // bilinear
    gpu::UniqueSampler deltaESampler_;  // nearest: uncovered pixels must not blend in
    gpu::UniqueDescriptorSetLayout setLayout_;
    gpu::UniquePipelineLayout pipelineLayout_;
    gpu::UniquePipeline pipelines_[2];  // [heatmap]: a render, or an error map coloured
    gpu::Buffer colormap_;  // the heatmap colours, a uniform buffer: viridis, then magma
    std::optional<gpu::DisplayTile> noDeltaE_;  // 1x1 "not covered", bound for tiles without one
    ImageMetric metric_ = ImageMetric::DeltaE00;
    float minDeltaE_ = 0.0f;
    float maxDeltaE_ = 10.0f;
    // Per frame slot: what its draws use, kept until the slot is drawn again.
    std::array<std::vector<std::shared_ptr<ShownImage>>, WindowRenderer::kFramesInFlight> inFlight_;
    // Per frame: what the callbacks need (they receive only the draw command).
    std::vector<ImageDraw> draws_;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    ImVec2 displayPosition_;
    ImVec2 displaySize_;
    ImVec2 framebufferScale_;
};

}  // namespace matevo::editor
