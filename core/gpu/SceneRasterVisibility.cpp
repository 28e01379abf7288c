#include "gpu/SceneRasterVisibility.h"

#include <algorithm>
#include <cstring>

#include <shaders/kSceneSurfacesFragmentSpirv.h>
#include <shaders/kSceneSurfacesVertexSpirv.h>

#include "gpu/GraphicsPipeline.h"
#include "gpu/VulkanObjects.h"
#include "mesh/Mesh.h"

namespace matevo::gpu {
namespace {

constexpr VkFormat kSurfaceFormat = VK_FORMAT_R32_UINT;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
// The standard 4x sample positions, the compute pass's (shaders/SceneVisibility.glsl).
constexpr VkSampleCountFlagBits kSamples = VK_SAMPLE_COUNT_4_BIT;
// No triangle (shaders/SceneVisibility.glsl's kNoSurface).
constexpr uint32_t kNoSurface = 0xffffffffu;

Result<UniqueRenderPass> createVisibilityRenderPass(VkDevice device) {
    VkAttachmentDescription attachments[2]{};
    for (VkAttachmentDescription& attachment : attachments) {
        attachment.samples = kSamples;
        attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        attachment.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        attachment.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;  // the shading pass's
    }
    attachments[0].format = kSurfaceFormat;
    attachments[1].format = kDepthFormat;
    const VkAttachmentReference surfaceOutput{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference depthOutput{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &surfaceOutput;
    subpass.pDepthStencilAttachment = &depthOutput;

    const VkPipelineStageFlags attachmentStages = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                  VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                                                  VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    const VkAccessFlags attachmentWrites =
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    VkSubpassDependency dependencies[2]{};
    // The previous frame's shading pass read the attachments before this frame clears them.
    VkSubpassDependency& previous = dependencies[0];
    previous.srcSubpass = VK_SUBPASS_EXTERNAL;
    previous.dstSubpass = 0;
    previous.srcStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    previous.srcAccessMask = 0;
    previous.dstStageMask = attachmentStages;
    previous.dstAccessMask = attachmentWrites | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    // This frame's shading pass reads them after the pass.
    VkSubpassDependency& shading = dependencies[1];
    shading.srcSubpass = 0;
    shading.dstSubpass = VK_SUBPASS_EXTERNAL;
    shading.srcStageMask = attachmentStages;
    shading.srcAccessMask = attachmentWrites;
    shading.dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    shading.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;

    return createRenderPass(device, attachments, subpass, dependencies);
}

}  // namespace

Status SceneRasterVisibility::supportedOn(const Device& device) {
    const std::string lacks =
        "Vulkan: " + device.name() + " cannot run the raster visibility pass: ";
    if (!device.primitiveIds())
        return environmentError(lacks + "no geometryShader feature (gl_PrimitiveID)");
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device.physicalDevice(), &properties);
    const VkPhysicalDeviceLimits& limits = properties.limits;
    if (!(limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts &
          limits.sampledImageIntegerSampleCounts & limits.sampledImageDepthSampleCounts & kSamples))
        return environmentError(lacks +
                                "no 4x multisampled integer and depth attachments to sample");
    for (const auto& [format, features] :
         {std::pair{kSurfaceFormat, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT},
          std::pair{kDepthFormat, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT}}) {
        VkFormatProperties formatProperties;
        vkGetPhysicalDeviceFormatProperties(device.physicalDevice(), format, &formatProperties);
        const VkFormatFeatureFlags needed = features | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
        if ((formatProperties.optimalTilingFeatures & needed) != needed)
            return environmentError(lacks + (format == kDepthFormat
                                                 ? "no sampled D32_SFLOAT depth buffer"
                                                 : "no sampled R32_UINT attachment"));
    }
    return Ok{};
}

Result<SceneRasterVisibility> SceneRasterVisibility::create(const Device& device,
                                                            CommandRunner& runner,
                                                            VkBuffer vertices,
                                                            std::span<const uint32_t> indices,
                                                            FillPath indexFill) {
    if (auto supported = supportedOn(device); !supported) return supported.error();
    const VkDevice vkDevice = device.handle();
    SceneRasterVisibility pass;
    pass.device_ = &device;
    pass.vertices_ = vertices;
    pass.indexCount_ = uint32_t(indices.size());
    auto indexBuffer = Buffer::createFilled(device, runner, std::as_bytes(indices),
                                            VK_BUFFER_USAGE_INDEX_BUFFER_BIT, indexFill);
    if (!indexBuffer) return indexBuffer.error();
    pass.indices_ = std::move(indexBuffer).value();

    auto descriptors = DescriptorSet::create(device, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                             VK_SHADER_STAGE_VERTEX_BIT);
    if (!descriptors) return descriptors.error();
    pass.descriptors_ = std::move(descriptors).value();
    auto renderPass = createVisibilityRenderPass(vkDevice);
    if (!renderPass) return renderPass.error();
    pass.renderPass_ = std::move(renderPass).value();
    auto pipelineLayout = createPipelineLayout(vkDevice, pass.descriptors_.layout());
    if (!pipelineLayout) return pipelineLayout.error();
    pass.pipelineLayout_ = std::move(pipelineLayout).value();

    // The vertex's position only (MeshVertex's other members are the shading pass's).
    const VkVertexInputAttributeDescription position{0, 0, VK_FORMAT_R32G32B32_SFLOAT,
                                                     uint32_t(offsetof(MeshVertex, position))};
    GraphicsPipelineSpec spec;
    spec.vertexSpirv = kSceneSurfacesVertexSpirv;
    spec.fragmentSpirv = kSceneSurfacesFragmentSpirv;
    spec.vertexBinding = {0, uint32_t(sizeof(MeshVertex)), VK_VERTEX_INPUT_RATE_VERTEX};
    spec.vertexAttributes = std::span(&position, 1);
    spec.cullMode = VK_CULL_MODE_BACK_BIT;
    spec.samples = kSamples;
    spec.depthTested = true;
    spec.layout = pass.pipelineLayout_.get();
    spec.renderPass = pass.renderPass_.get();
    spec.name = "scene visibility";
    auto pipeline = createGraphicsPipeline(vkDevice, spec);
    if (!pipeline) return pipeline.error();
    pass.pipeline_ = std::move(pipeline).value();
    return pass;
}

Status SceneRasterVisibility::prepareTarget(int width, int height) {
    if (width == width_ && height == height_) return Ok{};
    GpuImageSpec spec;
    spec.extent = {uint32_t(width), uint32_t(height), 1};
    spec.samples = kSamples;
    spec.format = kSurfaceFormat;
    spec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    auto surfaces = GpuImage::create(*device_, spec);
    if (!surfaces) return surfaces.error();
    spec.format = kDepthFormat;
    spec.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    spec.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    auto depths = GpuImage::create(*device_, spec);
    if (!depths) return depths.error();

    const VkImageView views[2] = {surfaces->view(), depths->view()};
    auto framebuffer = createFramebuffer(device_->handle(), renderPass_.get(), views,
                                         uint32_t(width), uint32_t(height));
    if (!framebuffer) return framebuffer.error();
    framebuffer_ = std::move(framebuffer).value();
    surfaces_ = std::move(surfaces).value();
    depths_ = std::move(depths).value();
    width_ = width;
    height_ = height;
    return Ok{};
}

Status SceneRasterVisibility::record(VkCommandBuffer commands,
                                     std::span<const DrawnInstance> drawn) {
    if (drawn_.size() < drawn.size_bytes() || drawn_.size() == 0) {
        auto grown = Buffer::create(
            *device_, std::max<VkDeviceSize>(drawn.size_bytes(), sizeof(DrawnInstance)),
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload);
        if (!grown) return grown.error();
        drawn_ = std::move(grown).value();
        descriptors_.bindBuffer(0, drawn_);
    }
    // An empty frame's span may hold no pointer at all, which memcpy must not be handed.
    if (!drawn.empty()) std::memcpy(drawn_.bytes().data(), drawn.data(), drawn.size_bytes());

    VkClearValue clears[2]{};
    clears[0].color.uint32[0] = kNoSurface;
    clears[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = renderPass_.get();
    begin.framebuffer = framebuffer_.get();
    begin.renderArea = {{0, 0}, {uint32_t(width_), uint32_t(height_)}};
    begin.clearValueCount = 2;
    begin.pClearValues = clears;
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    if (!drawn.empty()) {
        const VkViewport viewport{0.0f, 0.0f, float(width_), float(height_), 0.0f, 1.0f};
        vkCmdSetViewport(commands, 0, 1, &viewport);
        vkCmdSetScissor(commands, 0, 1, &begin.renderArea);
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
        const VkDescriptorSet set = descriptors_.handle();
        vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_.get(), 0,
                                1, &set, 0, nullptr);
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(commands, 0, 1, &vertices_, &offset);
        vkCmdBindIndexBuffer(commands, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(commands, indexCount_, uint32_t(drawn.size()), 0, 0, 0);
    }
    vkCmdEndRenderPass(commands);
    return Ok{};
}

}  // namespace matevo::gpu
