#include "ImageBridge.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "VulkanContext.h"
#include "color/Srgb.h"
#include "gpu/GraphicsPipeline.h"
#include "gpu/HeatmapColormap.h"
#include "gpu/VulkanObjects.h"
// SPIR-V generated at build time (app/editor/CMakeLists.txt); the arrays need <cstdint> first.
#include "shaders/image.frag.h"
#include "shaders/image.vert.h"

namespace matevo::editor {
namespace {

// Bindings of the image pipeline's descriptor set (shaders/image.frag).
enum Binding : std::uint32_t { kRenderBinding = 0, kDeltaEBinding = 1, kColormapBinding = 2 };

// Push constants: the vertex transform, then the fragment shader's heatmap settings.
struct FragmentSettings {
    float minDeltaE;
    float maxDeltaE;
    std::uint32_t colormapBase;  // 0: viridis (ΔE00), 256: magma (ꟻLIP)
};
constexpr std::uint32_t kTransformBytes = 4 * sizeof(float);

}  // namespace

ShownImage::ShownImage(std::shared_ptr<const gpu::DisplayTile> tile, VkDevice device,
                       VkDescriptorPool pool, VkDescriptorSet set)
    : tile_(std::move(tile)),
      device_(device),
      pool_(pool),
      set_(set),
      views_{View{this, false}, View{this, true}} {}

ShownImage::~ShownImage() { vkFreeDescriptorSets(device_, pool_, 1, &set_); }

Result<std::unique_ptr<ImageBridge>> ImageBridge::create(VulkanContext& context,
                                                         VkRenderPass renderPass) {
    std::unique_ptr<ImageBridge> bridge(new ImageBridge(context));
    bridge->device_ = context.device().handle();
    if (Status s = bridge->createLayouts(); !s) return s.error();
    if (Status s = bridge->createPipeline(renderPass); !s) return s.error();
    if (Status s = bridge->createSharedResources(); !s) return s.error();
    return bridge;
}

Status ImageBridge::createLayouts() {
    auto renderSampler = gpu::createSampler(device_, VK_FILTER_LINEAR);
    if (!renderSampler) return renderSampler.error();
    renderSampler_ = std::move(renderSampler).value();
    auto deltaESampler = gpu::createSampler(device_, VK_FILTER_NEAREST);
    if (!deltaESampler) return deltaESampler.error();
    deltaESampler_ = std::move(deltaESampler).value();

    VkDescriptorSetLayoutBinding bindings[3] = {};
    for (std::uint32_t binding : {kRenderBinding, kDeltaEBinding, kColormapBinding}) {
        bindings[binding].binding = binding;
        bindings[binding].descriptorType = binding == kColormapBinding
                                               ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER
                                               : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        bindings[binding].descriptorCount = 1;
        bindings[binding].stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
    }
    auto setLayout = gpu::createDescriptorSetLayout(device_, bindings);
    if (!setLayout) return setLayout.error();
    setLayout_ = std::move(setLayout).value();

    const VkPushConstantRange ranges[2] = {
        {VK_SHADER_STAGE_VERTEX_BIT, 0, kTransformBytes},
        {VK_SHADER_STAGE_FRAGMENT_BIT, kTransformBytes, sizeof(FragmentSettings)}};
    auto pipelineLayout = gpu::createPipelineLayout(device_, setLayout_.get(), ranges);
    if (!pipelineLayout) return pipelineLayout.error();
    pipelineLayout_ = std::move(pipelineLayout).value();
    return Ok{};
}

Status ImageBridge::createPipeline(VkRenderPass renderPass) {
    const VkVertexInputAttributeDescription attributes[3] = {
        {0, 0, VK_FORMAT_R32G32_SFLOAT, std::uint32_t(offsetof(ImDrawVert, pos))},
        {1, 0, VK_FORMAT_R32G32_SFLOAT, std::uint32_t(offsetof(ImDrawVert, uv))},
        {2, 0, VK_FORMAT_R8G8B8A8_UNORM, std::uint32_t(offsetof(ImDrawVert, col))}};
    gpu::GraphicsPipelineSpec spec;
    spec.vertexSpirv = kImageVertSpirv;
    spec.fragmentSpirv = kImageFragSpirv;
    spec.vertexBinding = {0, sizeof(ImDrawVert), VK_VERTEX_INPUT_RATE_VERTEX};
    spec.vertexAttributes = attributes;
    spec.alphaBlended = true;
    spec.layout = pipelineLayout_.get();
    spec.renderPass = renderPass;
    for (bool heatmap : {false, true}) {
        const VkBool32 showHeatmap = heatmap ? VK_TRUE : VK_FALSE;
        const VkSpecializationMapEntry entry{0, 0, sizeof showHeatmap};
        const VkSpecializationInfo specialization{1, &entry, sizeof showHeatmap, &showHeatmap};
        spec.fragmentSpecialization = &specialization;
        spec.name = heatmap ? "heatmap image" : "image";
        auto pipeline = gpu::createGraphicsPipeline(device_, spec);
        if (!pipeline) return pipeline.error();
        pipelines_[heatmap] = std::move(pipeline).value();
    }
    return Ok{};
}

Status ImageBridge::createSharedResources() {
    // Encoded once here rather than at every pixel of every frame.
    gpu::Colormap colors[2] = {gpu::heatmapColormap(), gpu::flipColormap()};
    for (auto& colormap : colors)
        for (auto& entry : colormap)
            for (int channel = 0; channel < 3; ++channel)
                entry[channel] = float(linearToSrgb(entry[channel]));
    auto colormap = gpu::Buffer::create(context_.device(), sizeof colors,
                                        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryUse::Upload);
    if (!colormap) return colormap.error();
    colormap_ = std::move(colormap).value();
    std::memcpy(colormap_.bytes().data(), colors, sizeof colors);

    auto tile = gpu::DisplayTile::create(context_.device(), 1, 1, true);
    if (!tile) return tile.error();
    noDeltaE_ = std::move(tile).value();
    const Image render(1, 1);
    const ErrorMap notCovered{ImageMetric::DeltaE00, 1, 1, {0.0f}, {0}, {}};
    const gpu::DisplayTile* tiles[] = {&*noDeltaE_};
    return gpu::uploadToTiles(context_.device(), context_.setupRunner(), tiles,
                              std::span(&render, 1), std::span(&notCovered, 1));
}

Result<std::shared_ptr<ShownImage>> ImageBridge::show(
    std::shared_ptr<const gpu::DisplayTile> tile) {
    auto allocated =
        gpu::allocateDescriptorSet(device_, context_.descriptorPool(), setLayout_.get());
    if (!allocated) return allocated.error();
    const VkDescriptorSet set = *allocated;
    const gpu::GpuImage& deltaE = tile->deltaE ? *tile->deltaE : *noDeltaE_->deltaE;
    const VkDescriptorImageInfo images[2] = {
        {renderSampler_.get(), tile->render.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {deltaESampler_.get(), deltaE.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
    const VkDescriptorBufferInfo colormap{colormap_.handle(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet writes[3] = {};
    for (std::uint32_t binding : {kRenderBinding, kDeltaEBinding, kColormapBinding}) {
        writes[binding].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[binding].dstSet = set;
        writes[binding].dstBinding = binding;
        writes[binding].descriptorCount = 1;
        writes[binding].descriptorType = binding == kColormapBinding
                                             ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER
                                             : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        if (binding == kColormapBinding)
            writes[binding].pBufferInfo = &colormap;
        else
            writes[binding].pImageInfo = &images[binding];
    }
    vkUpdateDescriptorSets(device_, 3, writes, 0, nullptr);
    return std::shared_ptr<ShownImage>(
        new ShownImage(std::move(tile), device_, context_.descriptorPool(), set));
}

Result<std::vector<std::shared_ptr<ShownImage>>> ImageBridge::upload(
    std::span<const Image> images) {
    std::vector<std::shared_ptr<gpu::DisplayTile>> tiles;
    std::vector<const gpu::DisplayTile*> targets;
    for (const Image& image : images) {
        auto tile = gpu::DisplayTile::create(context_.device(), image.width, image.height, false);
        if (!tile) return tile.error();
        tiles.push_back(std::make_shared<gpu::DisplayTile>(std::move(tile).value()));
        targets.push_back(tiles.back().get());
    }
    // One submission per size: the batch copy takes same-sized pictures.
    for (std::size_t first = 0; first < images.size();) {
        std::size_t end = first;
        while (end < images.size() && images[end].width == images[first].width &&
               images[end].height == images[first].height)
            ++end;
        if (Status s = gpu::uploadToTiles(context_.device(), context_.setupRunner(),
                                          std::span(targets).subspan(first, end - first),
                                          images.subspan(first, end - first), {});
            !s)
            return s.error();
        first = end;
    }
    std::vector<std::shared_ptr<ShownImage>> shown;
    for (auto& tile : tiles) {
        auto image = show(std::move(tile));
        if (!image) return image.error();
        shown.push_back(std::move(image).value());
    }
    return shown;
}

void ImageBridge::setHeatmap(ImageMetric metric, float minDeltaE, float maxDeltaE) {
    metric_ = metric;
    minDeltaE_ = minDeltaE;
    maxDeltaE_ = maxDeltaE;
}

void ImageBridge::prepare(ImDrawData& drawData, VkCommandBuffer commands, std::size_t frameSlot) {
    // The slot's previous frame has finished (WindowRenderer waited for it).
    std::vector<std::shared_ptr<ShownImage>>& used = inFlight_[frameSlot];
    used.clear();
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
            const auto* view = static_cast<const ShownImage::View*>(command.TextureId);
            used.push_back(view->owner->shared_from_this());
            draws_.push_back({this, view, command.ClipRect, command.ElemCount,
                              command.IdxOffset + globalIndex,
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

    const VkPipelineLayout layout = pipelineLayout_.get();
    vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_GRAPHICS,
                      pipelines_[image.view->heatmap].get());
    const VkDescriptorSet set = image.view->owner->set_;
    vkCmdBindDescriptorSets(commands_, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0,
                            nullptr);
    const VkViewport viewport{0, 0, framebufferWidth, framebufferHeight, 0, 1};
    vkCmdSetViewport(commands_, 0, 1, &viewport);
    const VkRect2D scissor{{std::int32_t(clipX0), std::int32_t(clipY0)},
                           {std::uint32_t(clipX1 - clipX0), std::uint32_t(clipY1 - clipY0)}};
    vkCmdSetScissor(commands_, 0, 1, &scissor);
    const float scale[2] = {2.0f / displaySize_.x, 2.0f / displaySize_.y};
    const float transform[4] = {scale[0], scale[1], -1.0f - displayPosition_.x * scale[0],
                                -1.0f - displayPosition_.y * scale[1]};
    vkCmdPushConstants(commands_, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, kTransformBytes,
                       transform);
    const bool flip = metric_ == ImageMetric::Flip;
    const FragmentSettings settings{flip ? 0.0f : minDeltaE_, flip ? 1.0f : maxDeltaE_,
                                    flip ? 256u : 0u};
    vkCmdPushConstants(commands_, layout, VK_SHADER_STAGE_FRAGMENT_BIT, kTransformBytes,
                       sizeof settings, &settings);
    vkCmdDrawIndexed(commands_, image.elementCount, 1, image.firstIndex, image.vertexOffset, 0);
}

}  // namespace matevo::editor
