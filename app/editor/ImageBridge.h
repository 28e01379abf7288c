#pragma once
// Shows our own images in Dear ImGui 1.86, whose Vulkan backend binds only its font texture.
// The UI draws images with ordinary ImGui calls (their ImTextureID is an EditorTexture*);
// before the backend renders, prepare() turns each such draw command into a callback that
// binds our pipeline (same vertex layout and transform as ImGui's) with the image's descriptor
// set and draws the command's own vertices, followed by a reset of ImGui's render state.
#include <cstddef>
#include <memory>
#include <vector>

#include <imgui.h>
#include <vulkan/vulkan.h>

#include "HostBuffer.h"
#include "Rgba8Image.h"

namespace matevo::editor {

class VulkanContext;

class EditorTexture {
public:
    EditorTexture(const VulkanContext& context, VkDescriptorSetLayout layout, VkSampler sampler,
                  int width, int height);
    ~EditorTexture();
    EditorTexture(const EditorTexture&) = delete;
    EditorTexture& operator=(const EditorTexture&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    VkDescriptorSet descriptorSet() const { return descriptorSet_; }
    ImTextureID id() { return static_cast<ImTextureID>(this); }

    void stage(const Rgba8Image& pixels);         // copies into the staging buffer
    void recordUpload(VkCommandBuffer commands);  // no-op unless something was staged

private:
    VkDevice device_;
    VkDescriptorPool pool_;
    int width_;
    int height_;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    VkDescriptorSet descriptorSet_ = VK_NULL_HANDLE;
    HostBuffer staging_;
    bool staged_ = false;
    bool initialised_ = false;  // layout is SHADER_READ_ONLY after the first upload
};

class ImageBridge {
public:
    ImageBridge(const VulkanContext& context, VkRenderPass renderPass);
    ~ImageBridge();
    ImageBridge(const ImageBridge&) = delete;
    ImageBridge& operator=(const ImageBridge&) = delete;

    // Puts pixels into texture `slot` (created or resized as needed) and returns its id. Call
    // only while no frame is in flight (WindowRenderer::waitIdle).
    ImTextureID setImage(std::size_t slot, const Rgba8Image& pixels);
    void recordUploads(VkCommandBuffer commands);

    // Rewrites `drawData` so our images draw through our pipeline into `commands`.
    void prepare(ImDrawData& drawData, VkCommandBuffer commands);

private:
    struct ImageDraw {
        ImageBridge* bridge;
        const EditorTexture* texture;
        ImVec4 clipRect;
        unsigned elementCount;
        unsigned firstIndex;
        int vertexOffset;
    };
    static void drawCallback(const ImDrawList* list, const ImDrawCmd* command);
    void draw(const ImageDraw& image) const;
    void createPipeline(VkRenderPass renderPass);

    const VulkanContext& context_;
    VkDevice device_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    std::vector<std::unique_ptr<EditorTexture>> textures_;
    // Per frame: what the callbacks need (they receive only the draw command).
    std::vector<ImageDraw> draws_;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    ImVec2 displayPosition_;
    ImVec2 displaySize_;
    ImVec2 framebufferScale_;
};

}  // namespace matevo::editor
