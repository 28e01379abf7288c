#include "ImageBridge.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "VulkanContext.h"
#include "gpu/GpuImage.h"
// SPIR-V generated at build time (app/CMakeLists.txt); the arrays need <cstdint> first.
#include "shaders/image.frag.h"
#include "shaders/image.vert.h"

namespace matevo::editor {
namespace {

VkShaderModule createShader(VkDevice device, const std::uint32_t* code, std::size_t bytes) {
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = bytes;
    info.pCode = code;
    VkShaderModule module = VK_NULL_HANDLE;
    check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
    return module;
}

}  // namespace

EditorTexture::EditorTexture(const VulkanContext& context, VkDescriptorSetLayout layout,
                             VkSampler sampler, int width, int height)
    : device_(context.device()),
      pool_(context.descriptorPool()),
      width_(width),
      height_(height),
      staging_(context, VkDeviceSize(width) * VkDeviceSize(height) * 4,
               VK_BUFFER_USAGE_TRANSFER_SRC_BIT) {
    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.imageType = VK_IMAGE_TYPE_2D;
    // UNORM holding sRGB-encoded bytes: the window is UNORM too, so values pass through as-is.
    info.format = VK_FORMAT_R8G8B8A8_UNORM;
    info.extent = {std::uint32_t(width), std::uint32_t(height), 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    check(vkCreateImage(device_, &info, nullptr, &image_), "vkCreateImage");
    VkMemoryRequirements needs;
    vkGetImageMemoryRequirements(device_, image_, &needs);
    memory_ = context.allocateMemory(needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    check(vkBindImageMemory(device_, image_, memory_, 0), "vkBindImageMemory");

    VkImageViewCreateInfo view{};
    view.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    view.image = image_;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = info.format;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    check(vkCreateImageView(device_, &view, nullptr, &view_), "vkCreateImageView");

    VkDescriptorSetAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    allocate.descriptorPool = pool_;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &layout;
    check(vkAllocateDescriptorSets(device_, &allocate, &descriptorSet_),
          "vkAllocateDescriptorSets");
    VkDescriptorImageInfo imageInfo{sampler, view_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = descriptorSet_;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &imageInfo;
    vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
}

EditorTexture::~EditorTexture() {
    vkFreeDescriptorSets(device_, pool_, 1, &descriptorSet_);
    vkDestroyImageView(device_, view_, nullptr);
    vkDestroyImage(device_, image_, nullptr);
    vkFreeMemory(device_, memory_, nullptr);
}

void EditorTexture::stage(const Rgba8Image& pixels) {
    std::memcpy(staging_.data(), pixels.rgba.data(),
                std::min<std::size_t>(pixels.rgba.size(), std::size_t(staging_.size())));
    staged_ = true;
}

void EditorTexture::recordUpload(VkCommandBuffer commands) {
    if (!staged_) return;
    gpu::transitionImage(
        commands, image_,
        initialised_ ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
        VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {std::uint32_t(width_), std::uint32_t(height_), 1};
    vkCmdCopyBufferToImage(commands, staging_.buffer(), image_,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    gpu::transitionImage(commands, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                         VK_ACCESS_SHADER_READ_BIT);
    staged_ = false;
    initialised_ = true;
}

ImageBridge::ImageBridge(const VulkanContext& context, VkRenderPass renderPass)
    : context_(context), device_(context.device()) {
    VkSamplerCreateInfo sampler{};
    sampler.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    sampler.magFilter = VK_FILTER_LINEAR;
    sampler.minFilter = VK_FILTER_LINEAR;
    sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    sampler.addressModeU = sampler.addressModeV = sampler.addressModeW =
        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sampler.maxLod = 0.0f;
    check(vkCreateSampler(device_, &sampler, nullptr, &sampler_), "vkCreateSampler");

    VkDescriptorSetLayoutBinding binding{};
    binding.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    binding.descriptorCount = 1;
    binding.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
    VkDescriptorSetLayoutCreateInfo setLayout{};
    setLayout.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    setLayout.bindingCount = 1;
    setLayout.pBindings = &binding;
    check(vkCreateDescriptorSetLayout(device_, &setLayout, nullptr, &setLayout_),
          "vkCreateDescriptorSetLayout");
    const VkPushConstantRange transform{VK_SHADER_STAGE_VERTEX_BIT, 0, 4 * sizeof(float)};
    VkPipelineLayoutCreateInfo layout{};
    layout.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layout.setLayoutCount = 1;
    layout.pSetLayouts = &setLayout_;
    layout.pushConstantRangeCount = 1;
    layout.pPushConstantRanges = &transform;
    check(vkCreatePipelineLayout(device_, &layout, nullptr, &pipelineLayout_),
          "vkCreatePipelineLayout");
    createPipeline(renderPass);
}

ImageBridge::~ImageBridge() {
    textures_.clear();
    vkDestroyPipeline(device_, pipeline_, nullptr);
    vkDestroyPipelineLayout(device_, pipelineLayout_, nullptr);
    vkDestroyDescriptorSetLayout(device_, setLayout_, nullptr);
    vkDestroySampler(device_, sampler_, nullptr);
}

void ImageBridge::createPipeline(VkRenderPass renderPass) {
    const VkShaderModule vertex = createShader(device_, kImageVertSpirv, sizeof kImageVertSpirv);
    const VkShaderModule fragment = createShader(device_, kImageFragSpirv, sizeof kImageFragSpirv);
    VkPipelineShaderStageCreateInfo stages[2] = {};
    stages[0].sType = stages[1].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vertex;
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = fragment;
    stages[1].pName = "main";

    const VkVertexInputBindingDescription binding{0, sizeof(ImDrawVert),
                                                  VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription attributes[3] = {
        {0, 0, VK_FORMAT_R32G32_SFLOAT, std::uint32_t(offsetof(ImDrawVert, pos))},
        {1, 0, VK_FORMAT_R32G32_SFLOAT, std::uint32_t(offsetof(ImDrawVert, uv))},
        {2, 0, VK_FORMAT_R8G8B8A8_UNORM, std::uint32_t(offsetof(ImDrawVert, col))}};
    VkPipelineVertexInputStateCreateInfo vertexInput{};
    vertexInput.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = 3;
    vertexInput.pVertexAttributeDescriptions = attributes;
    VkPipelineInputAssemblyStateCreateInfo assembly{};
    assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewport{};
    viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{};
    raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{};
    multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    // Straight-alpha "over", as ImGui blends.
    VkPipelineColorBlendAttachmentState blend{};
    blend.blendEnable = VK_TRUE;
    blend.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
    blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend.colorBlendOp = VK_BLEND_OP_ADD;
    blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend.alphaBlendOp = VK_BLEND_OP_ADD;
    blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                           VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blendState{};
    blendState.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
    blendState.attachmentCount = 1;
    blendState.pAttachments = &blend;
    VkPipelineDepthStencilStateCreateInfo depth{};
    depth.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
    const VkDynamicState dynamicStates[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{};
    dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamicStates;

    VkGraphicsPipelineCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blendState;
    info.pDynamicState = &dynamic;
    info.layout = pipelineLayout_;
    info.renderPass = renderPass;
    check(vkCreateGraphicsPipelines(device_, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
          "vkCreateGraphicsPipelines");
    vkDestroyShaderModule(device_, vertex, nullptr);
    vkDestroyShaderModule(device_, fragment, nullptr);
}

ImTextureID ImageBridge::setImage(std::size_t slot, const Rgba8Image& pixels) {
    if (slot >= textures_.size()) textures_.resize(slot + 1);
    auto& texture = textures_[slot];
    if (!texture || texture->width() != pixels.width || texture->height() != pixels.height)
        texture = std::make_unique<EditorTexture>(context_, setLayout_, sampler_, pixels.width,
                                                  pixels.height);
    texture->stage(pixels);
    return texture->id();
}

void ImageBridge::recordUploads(VkCommandBuffer commands) {
    for (auto& texture : textures_)
        if (texture) texture->recordUpload(commands);
}

void ImageBridge::prepare(ImDrawData& drawData, VkCommandBuffer commands) {
    commands_ = commands;
    displayPosition_ = drawData.DisplayPos;
    displaySize_ = drawData.DisplaySize;
    framebufferScale_ = drawData.FramebufferScale;
    const ImTextureID font = ImGui::GetIO().Fonts->TexID;
    std::size_t imageCount = 0;
    for (int l = 0; l < drawData.CmdListsCount; ++l)
        for (const ImDrawCmd& command : drawData.CmdLists[l]->CmdBuffer)
            imageCount += !command.UserCallback && command.TextureId != font;
    draws_.clear();
    draws_.reserve(imageCount);  // the callbacks hold pointers into it

    unsigned globalIndex = 0;
    int globalVertex = 0;
    for (int l = 0; l < drawData.CmdListsCount; ++l) {
        ImDrawList& list = *drawData.CmdLists[l];
        ImVector<ImDrawCmd> rewritten;
        for (const ImDrawCmd& command : list.CmdBuffer) {
            if (command.UserCallback || command.TextureId == font) {
                rewritten.push_back(command);
                continue;
            }
            draws_.push_back({this, static_cast<const EditorTexture*>(command.TextureId),
                              command.ClipRect, command.ElemCount, command.IdxOffset + globalIndex,
                              int(command.VtxOffset) + globalVertex});
            ImDrawCmd callback = command;
            callback.UserCallback = &ImageBridge::drawCallback;
            callback.UserCallbackData = &draws_.back();
            rewritten.push_back(callback);
            ImDrawCmd reset = command;
            reset.UserCallback = ImDrawCallback_ResetRenderState;
            rewritten.push_back(reset);
        }
        list.CmdBuffer.swap(rewritten);
        globalIndex += unsigned(list.IdxBuffer.Size);
        globalVertex += list.VtxBuffer.Size;
    }
}

void ImageBridge::drawCallback(const ImDrawList*, const ImDrawCmd* command) {
    const auto* image = static_cast<const ImageDraw*>(command->UserCallbackData);
    image->bridge->draw(*image);
}

void ImageBridge::draw(const ImageDraw& image) const {
    const float framebufferWidth = displaySize_.x * framebufferScale_.x;
    const float framebufferHeight = displaySize_.y * framebufferScale_.y;
    const float clipX0 =
        std::max(0.0f, (image.clipRect.x - displayPosition_.x) * framebufferScale_.x);
    const float clipY0 =
        std::max(0.0f, (image.clipRect.y - displayPosition_.y) * framebufferScale_.y);
    const float clipX1 =
        std::min(framebufferWidth, (image.clipRect.z - displayPosition_.x) * framebufferScale_.x);
    const float clipY1 =
        std::min(framebufferHeight, (image.clipRect.w - displayPosition_.y) * framebufferScale_.y);
    if (clipX1 <= clipX0 || clipY1 <= clipY0) return;

    vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    const VkDescriptorSet set = image.texture->descriptorSet();
    vkCmdBindDescriptorSets(commands_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &set,
                            0, nullptr);
    const VkViewport viewport{0, 0, framebufferWidth, framebufferHeight, 0, 1};
    vkCmdSetViewport(commands_, 0, 1, &viewport);
    const VkRect2D scissor{{std::int32_t(clipX0), std::int32_t(clipY0)},
                           {std::uint32_t(clipX1 - clipX0), std::uint32_t(clipY1 - clipY0)}};
    vkCmdSetScissor(commands_, 0, 1, &scissor);
    const float scale[2] = {2.0f / displaySize_.x, 2.0f / displaySize_.y};
    const float transform[4] = {scale[0], scale[1], -1.0f - displayPosition_.x * scale[0],
                                -1.0f - displayPosition_.y * scale[1]};
    vkCmdPushConstants(commands_, pipelineLayout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof transform,
                       transform);
    vkCmdDrawIndexed(commands_, image.elementCount, 1, image.firstIndex, image.vertexOffset, 0);
}

}  // namespace matevo::editor
