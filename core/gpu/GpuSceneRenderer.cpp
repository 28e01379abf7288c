#include "gpu/GpuSceneRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <shaders/kSceneRasterFragmentSpirv.h>
#include <shaders/kSceneRasterVertexSpirv.h>

#include "gpu/GraphicsPipeline.h"
#include "gpu/ShaderModule.h"
#include "gpu/VulkanError.h"
#include "mesh/MeshSimplification.h"

namespace matevo::gpu {
namespace {

constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
// Screen pixels per triangle of a level of detail, counted over the instance's whole disc
// (about half the triangles face away): smaller triangles cost lavapipe as much as these and
// change nothing visible.
constexpr double kPixelsPerTriangle = 2.0;

enum Binding : uint32_t {
    kInstances = 0,
    kFrame = 1,
    kLobeEntries = 2,
    kMaterials = 3,
    kRoughness = 4,
    kBaseColor = 5,
    kEnvironment = 6,
};

// std430 mirrors of the shaders' blocks.
struct GpuInstance {
    float transform[16];
    uint32_t material[4];
};

struct GpuFrame {
    float viewProjection[16];
    float cameraPosition[4];
    float toLight[4];
    float lightRadiance[4];
    float ambient[4];  // w: environment levels
};

void store(float (&target)[4], const std::array<double, 3>& xyz, double w) {
    for (int c = 0; c < 3; ++c) target[c] = float(xyz[std::size_t(c)]);
    target[3] = float(w);
}

GpuFrame toGpu(const SceneFrame& frame, const SceneSettings& scene,
               const GpuSceneTextures& textures) {
    const SceneCamera& camera = frame.camera;
    const glm::dmat4 view = glm::lookAt(camera.position, camera.target, glm::dvec3(0, 1, 0));
    // Depth range [0, 1]; the near plane close enough for a camera inside the crowd.
    glm::dmat4 projection = glm::perspectiveRH_ZO(
        camera.fieldOfViewDegrees * std::numbers::pi / 180.0,
        double(frame.width) / double(frame.height), 0.05, 1000.0);
    projection[1][1] *= -1.0;  // Vulkan's framebuffer y points down
    const glm::mat4 viewProjection(projection * view);
    GpuFrame gpu{};
    std::memcpy(gpu.viewProjection, glm::value_ptr(viewProjection), sizeof gpu.viewProjection);
    store(gpu.cameraPosition, {camera.position.x, camera.position.y, camera.position.z}, 1.0);
    const glm::dvec3 toLight = glm::normalize(glm::dvec3(
        scene.lightDirection[0], scene.lightDirection[1], scene.lightDirection[2]));
    store(gpu.toLight, {toLight.x, toLight.y, toLight.z}, 0.0);
    store(gpu.lightRadiance, scene.lightRadiance, 0.0);
    store(gpu.ambient, ambientRadiance(scene), textures.environmentLevels());
    return gpu;
}

Result<Buffer> createFilledBuffer(const Device& device, std::span<const std::byte> bytes,
                                  VkBufferUsageFlags usage) {
    auto buffer = Buffer::create(device, std::max<VkDeviceSize>(bytes.size(), 16), usage,
                                 MemoryUse::Upload);
    if (!buffer) return buffer;
    std::memcpy(buffer->bytes().data(), bytes.data(), bytes.size());
    return buffer;
}

// Multisampled colour and depth, resolved into a single-sample image that a transfer (or, in
// the editor, a shader) reads after the pass.
Result<UniqueRenderPass> createRenderPass(VkDevice device) {
    VkAttachmentDescription attachments[3]{};
    attachments[0].format = GpuSceneRenderer::kColorFormat;
    attachments[0].samples = GpuSceneRenderer::kSamples;
    attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[0].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    attachments[1] = attachments[0];
    attachments[1].format = kDepthFormat;
    attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    attachments[2] = attachments[0];
    attachments[2].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[2].loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[2].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[2].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;

    const VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference resolve{2, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &color;
    subpass.pResolveAttachments = &resolve;
    subpass.pDepthStencilAttachment = &depth;

    const VkPipelineStageFlags attachmentStages =
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
        VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    const VkAccessFlags attachmentAccess =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    VkSubpassDependency dependencies[2]{};
    // The previous frame's attachment writes and its read of the resolved image come first.
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask = attachmentStages | VK_PIPELINE_STAGE_TRANSFER_BIT |
                                   VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    dependencies[0].srcAccessMask = attachmentAccess;
    dependencies[0].dstStageMask = attachmentStages;
    dependencies[0].dstAccessMask = attachmentAccess;
    // The resolved image is read by a transfer after the pass.
    dependencies[1].srcSubpass = 0;
    dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;

    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 3;
    info.pAttachments = attachments;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 2;
    info.pDependencies = dependencies;
    VkRenderPass renderPass = VK_NULL_HANDLE;
    if (VkResult result = vkCreateRenderPass(device, &info, nullptr, &renderPass);
        result != VK_SUCCESS)
        return vulkanError("creating a render pass", result);
    return UniqueRenderPass(device, renderPass);
}

// The fragment stage is specialised for the textures and the environment the scene has.
Result<UniquePipeline> createPipeline(VkDevice device, VkRenderPass renderPass,
                                      VkPipelineLayout layout,
                                      const GpuSceneTextures& textures) {
    const uint32_t specialization[2] = {textures.textured() ? 1u : 0u,
                                        textures.environmentLevels() > 0 ? 1u : 0u};
    const SpecializationConstants constants(specialization);
    const VkVertexInputAttributeDescription attributes[3] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(MeshVertex, position))},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(MeshVertex, normal))},
        {2, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(MeshVertex, uv))},
    };
    GraphicsPipelineSpec spec;
    spec.vertexSpirv = kSceneRasterVertexSpirv;
    spec.fragmentSpirv = kSceneRasterFragmentSpirv;
    spec.fragmentSpecialization = constants.info();
    spec.vertexBinding = {0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX};
    spec.vertexAttributes = attributes;
    // The projection's y flip keeps the mesh's counter-clockwise front faces so on screen.
    spec.cullMode = VK_CULL_MODE_BACK_BIT;
    spec.samples = GpuSceneRenderer::kSamples;
    spec.depthTested = true;
    spec.layout = layout;
    spec.renderPass = renderPass;
    spec.name = "scene";
    return createGraphicsPipeline(device, spec);
}

Status requireMultisampling(const Device& device) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device.physicalDevice(), &properties);
    const VkSampleCountFlags supported = properties.limits.framebufferColorSampleCounts &
                                         properties.limits.framebufferDepthSampleCounts;
    if ((supported & GpuSceneRenderer::kSamples) == 0)
        return Error{"Vulkan: " + device.name() + " cannot render with 4x multisampling"};
    return Ok{};
}

}  // namespace

Result<GpuSceneRenderer> GpuSceneRenderer::create(const Device& device, CommandRunner& runner,
                                                  const FgdTables& tables,
                                                  const SceneTextures& textures,
                                                  const Mesh& mesh) {
    if (auto ok = requireMultisampling(device); !ok) return ok.error();
    const VkDevice vkDevice = device.handle();
    GpuSceneRenderer renderer;
    renderer.device_ = &device;
    renderer.tables_ = &tables;
    auto uploaded = GpuSceneTextures::create(device, runner, textures);
    if (!uploaded) return uploaded.error();
    renderer.textures_ = std::move(uploaded).value();

    // Every level in one vertex and one index buffer.
    std::vector<MeshVertex> allVertices;
    std::vector<uint32_t> allIndices;
    for (const Mesh& level : levelsOfDetail(mesh)) {
        renderer.levels_.push_back({uint32_t(allIndices.size()), uint32_t(level.indices.size()),
                                    int32_t(allVertices.size())});
        allVertices.insert(allVertices.end(), level.vertices.begin(), level.vertices.end());
        allIndices.insert(allIndices.end(), level.indices.begin(), level.indices.end());
    }
    auto vertices = createFilledBuffer(device, std::as_bytes(std::span(allVertices)),
                                       VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    if (!vertices) return vertices.error();
    auto indices = createFilledBuffer(device, std::as_bytes(std::span(allIndices)),
                                      VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    if (!indices) return indices.error();
    auto frameBuffer = Buffer::create(device, sizeof(GpuFrame), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                      MemoryUse::Upload);
    if (!frameBuffer) return frameBuffer.error();
    renderer.vertices_ = std::move(vertices).value();
    renderer.indices_ = std::move(indices).value();
    renderer.frameBuffer_ = std::move(frameBuffer).value();

    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    auto descriptors = DescriptorSet::create(
        device, {storage, storage, storage, storage, sampled, sampled, sampled},
        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
    if (!descriptors) return descriptors.error();
    renderer.descriptors_ = std::move(descriptors).value();
    renderer.descriptors_.bindBuffer(kFrame, renderer.frameBuffer_);
    renderer.textures_.bind(renderer.descriptors_, kRoughness, kBaseColor, kEnvironment);

    auto renderPass = createRenderPass(vkDevice);
    if (!renderPass) return renderPass.error();
    renderer.renderPass_ = std::move(renderPass).value();
    const VkDescriptorSetLayout setLayout = renderer.descriptors_.layout();
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    if (VkResult result = vkCreatePipelineLayout(vkDevice, &layoutInfo, nullptr, &pipelineLayout);
        result != VK_SUCCESS)
        return vulkanError("creating a pipeline layout", result);
    renderer.pipelineLayout_ = UniquePipelineLayout(vkDevice, pipelineLayout);
    auto pipeline = createPipeline(vkDevice, renderer.renderPass_.get(), pipelineLayout,
                                   renderer.textures_);
    if (!pipeline) return pipeline.error();
    renderer.pipeline_ = std::move(pipeline).value();
    return renderer;
}

Status GpuSceneRenderer::setMaterials(std::span<const MaterialInstance> materials) {
    if (materials.empty()) return Error{"the scene needs at least one material"};
    if (auto uploaded = materials_.upload(*device_, *tables_, materials); !uploaded)
        return uploaded.error();
    materialCount_ = uint32_t(materials.size());
    descriptors_.bindBuffer(kMaterials, materials_.materials());
    descriptors_.bindBuffer(kLobeEntries, materials_.lobeEntries());
    return Ok{};
}

Status GpuSceneRenderer::prepareTarget(int width, int height) {
    if (width == width_ && height == height_) return Ok{};
    const VkExtent3D extent{uint32_t(width), uint32_t(height), 1};
    GpuImageSpec colorSpec;
    colorSpec.format = kColorFormat;
    colorSpec.extent = extent;
    colorSpec.samples = kSamples;
    colorSpec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    GpuImageSpec depthSpec = colorSpec;
    depthSpec.format = kDepthFormat;
    depthSpec.usage =
        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    depthSpec.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    GpuImageSpec resolvedSpec = colorSpec;
    resolvedSpec.samples = VK_SAMPLE_COUNT_1_BIT;
    resolvedSpec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                         VK_IMAGE_USAGE_SAMPLED_BIT;
    auto color = GpuImage::create(*device_, colorSpec);
    if (!color) return color.error();
    auto depth = GpuImage::create(*device_, depthSpec);
    if (!depth) return depth.error();
    auto resolved = GpuImage::create(*device_, resolvedSpec);
    if (!resolved) return resolved.error();

    const VkImageView views[3] = {color->view(), depth->view(), resolved->view()};
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_.get();
    info.attachmentCount = 3;
    info.pAttachments = views;
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    if (VkResult result = vkCreateFramebuffer(device_->handle(), &info, nullptr, &framebuffer);
        result != VK_SUCCESS)
        return vulkanError("creating a framebuffer", result);
    framebuffer_ = UniqueFramebuffer(device_->handle(), framebuffer);
    color_ = std::move(color).value();
    depth_ = std::move(depth).value();
    resolved_ = std::move(resolved).value();
    width_ = width;
    height_ = height;
    return Ok{};
}

Status GpuSceneRenderer::prepareInstances(const SceneFrame& frame) {
    const std::span<const SceneInstance> instances = frame.instances;
    struct Placed {
        std::size_t instance;
        std::size_t level;
        double distance;
    };
    std::vector<Placed> placed;
    placed.reserve(instances.size());
    const SceneCamera& camera = frame.camera;
    // Pixels per unit length at distance 1 from the camera.
    const double focalPixels =
        0.5 * frame.height / std::tan(camera.fieldOfViewDegrees * std::numbers::pi / 360.0);
    for (std::size_t i = 0; i < instances.size(); ++i) {
        if (instances[i].material >= materialCount_)
            return Error{"scene instance " + std::to_string(i) + " names material " +
                         std::to_string(instances[i].material) + " of " +
                         std::to_string(materialCount_)};
        // Meshes fit the unit sphere (core/mesh/Mesh.h): its image is a disc of about this
        // radius; the level is the finest whose triangles get kPixelsPerTriangle of it.
        const glm::mat4& transform = instances[i].transform;
        const double scale = glm::length(glm::dvec3(transform[0]));
        const double distance = glm::length(glm::dvec3(transform[3]) - camera.position);
        const double radius = distance > scale ? focalPixels * scale / distance : INFINITY;
        const double pixels = std::numbers::pi * radius * radius;
        std::size_t level = 0;
        while (level + 1 < levels_.size() &&
               double(levels_[level].indexCount / 3) * kPixelsPerTriangle > pixels)
            ++level;
        placed.push_back({i, level, distance});
    }
    std::stable_sort(placed.begin(), placed.end(), [](const Placed& a, const Placed& b) {
        return a.level != b.level ? a.level < b.level : a.distance < b.distance;
    });
    std::vector<GpuInstance> gpuInstances(std::max<std::size_t>(instances.size(), 1));
    levelInstances_.assign(levels_.size(), 0);
    for (std::size_t i = 0; i < placed.size(); ++i) {
        const SceneInstance& instance = instances[placed[i].instance];
        std::memcpy(gpuInstances[i].transform, glm::value_ptr(instance.transform),
                    sizeof gpuInstances[i].transform);
        gpuInstances[i].material[0] = instance.material;
        ++levelInstances_[placed[i].level];
    }
    const VkDeviceSize bytes = gpuInstances.size() * sizeof(GpuInstance);
    if (instances_.size() < bytes) {
        auto grown = Buffer::create(*device_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                    MemoryUse::Upload);
        if (!grown) return grown.error();
        instances_ = std::move(grown).value();
        descriptors_.bindBuffer(kInstances, instances_);
    }
    std::memcpy(instances_.bytes().data(), gpuInstances.data(), bytes);
    return Ok{};
}

Status GpuSceneRenderer::record(VkCommandBuffer commands, const SceneFrame& frame,
                                const SceneSettings& scene) {
    if (frame.width <= 0 || frame.height <= 0) return Error{"the scene image is empty"};
    if (materialCount_ == 0) return Error{"the scene has no materials (setMaterials)"};
    if (auto ok = prepareTarget(frame.width, frame.height); !ok) return ok.error();
    if (auto ok = prepareInstances(frame); !ok) return ok.error();
    const GpuFrame gpuFrame = toGpu(frame, scene, textures_);
    std::memcpy(frameBuffer_.bytes().data(), &gpuFrame, sizeof gpuFrame);

    VkClearValue clears[3]{};
    clears[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = renderPass_.get();
    begin.framebuffer = framebuffer_.get();
    begin.renderArea = {{0, 0}, {uint32_t(frame.width), uint32_t(frame.height)}};
    begin.clearValueCount = 3;
    begin.pClearValues = clears;
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    const VkViewport viewport{0.0f, 0.0f, float(frame.width), float(frame.height), 0.0f, 1.0f};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &begin.renderArea);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
    const VkDescriptorSet set = descriptors_.handle();
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_.get(), 0, 1,
                            &set, 0, nullptr);
    const VkBuffer vertexBuffer = vertices_.handle();
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(commands, 0, 1, &vertexBuffer, &offset);
    vkCmdBindIndexBuffer(commands, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
    uint32_t firstInstance = 0;
    for (std::size_t level = 0; level < levels_.size(); ++level) {
        if (levelInstances_[level] > 0)
            vkCmdDrawIndexed(commands, levels_[level].indexCount, levelInstances_[level],
                             levels_[level].firstIndex, levels_[level].vertexOffset,
                             firstInstance);
        firstInstance += levelInstances_[level];
    }
    vkCmdEndRenderPass(commands);
    return Ok{};
}

Result<Image> GpuSceneRenderer::render(CommandRunner& runner, const SceneFrame& frame,
                                       const SceneSettings& scene) {
    const VkDeviceSize bytes = VkDeviceSize(frame.width) * VkDeviceSize(frame.height) * 8;
    auto readback = Buffer::create(*device_, std::max<VkDeviceSize>(bytes, 8),
                                   VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
    if (!readback) return readback.error();
    auto commands = runner.begin();
    if (!commands) return commands.error();
    if (auto recorded = record(*commands, frame, scene); !recorded) return recorded.error();
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {uint32_t(frame.width), uint32_t(frame.height), 1};
    vkCmdCopyImageToBuffer(*commands, resolved_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback->handle(), 1, &region);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(*commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                         1, &toHost, 0, nullptr, 0, nullptr);
    if (auto submitted = runner.submitAndWait(); !submitted) return submitted.error();

    // The resolve averaged (radiance, 1) over covered samples and (0, 0) elsewhere: colour is
    // premultiplied by coverage; divide it out for straight alpha like the sphere renderers.
    Image image(frame.width, frame.height);
    const auto halves = readback->as<const uint16_t>();
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        float* pixel = &image.rgba[4 * i];
        for (int c = 0; c < 4; ++c) pixel[c] = glm::unpackHalf1x16(halves[4 * i + std::size_t(c)]);
        if (pixel[3] > 0.0f)
            for (int c = 0; c < 3; ++c) pixel[c] /= pixel[3];
    }
    return image;
}

}  // namespace matevo::gpu
