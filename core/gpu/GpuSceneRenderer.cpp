#include "gpu/GpuSceneRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <shaders/kSceneDisplaySpirv.h>
#include <shaders/kSceneShadeFragmentSpirv.h>
#include <shaders/kSceneShadeVertexSpirv.h>
#include <shaders/kSceneSurfaceFragmentSpirv.h>
#include <shaders/kSceneSurfaceVertexSpirv.h>

#include "gpu/GraphicsPipeline.h"
#include "gpu/ShaderModule.h"
#include "gpu/VulkanError.h"
#include "mesh/MeshSimplification.h"
#include "scene/EnvironmentBackdrop.h"

namespace matevo::gpu {
namespace {

constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkFormat kSurfaceFormat = VK_FORMAT_R32G32B32A32_UINT;  // shaders/SceneSurface.glsl
// Screen pixels per triangle of a level of detail, counted over the instance's whole disc
// (about half the triangles face away): smaller triangles change nothing visible.
constexpr double kPixelsPerTriangle = 2.0;

enum Binding : uint32_t {
    kInstances = 0,
    kFrame = 1,
    kLobeEntries = 2,
    kMaterials = 3,
    kRoughness = 4,
    kBaseColor = 5,
    kEnvironment = 6,
    kSurfaces = 7,
};

// SceneDisplay.comp's bindings and push constants.
enum DisplayBinding : uint32_t {
    kDisplayRadiance = 0,
    kDisplayFrame = 1,
    kDisplayEnvironment = 2,
    kDisplayTarget = 3,
};

struct DisplayConstants {
    float exposureScale;
    float backdropAlpha;
    uint32_t aces;
};

enum Attachment : uint32_t {
    kSurfaceAttachment = 0,
    kDepthAttachment = 1,
    kRadianceAttachment = 2
};

// std430 mirrors of the shaders' blocks.
struct GpuInstance {
    float transform[16];
    uint32_t material[4];
};

struct GpuFrame {
    float viewProjection[16];
    float inverseViewProjection[16];
    float cameraPosition[4];
    float toLight[4];
    float lightRadiance[4];
    float ambient[4];  // w: environment levels
    float viewportSize[4];
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
    glm::dmat4 projection =
        glm::perspectiveRH_ZO(camera.fieldOfViewDegrees * std::numbers::pi / 180.0,
                              double(frame.width) / double(frame.height), 0.05, 1000.0);
    projection[1][1] *= -1.0;  // Vulkan's framebuffer y points down
    const glm::mat4 viewProjection(projection * view);
    const glm::mat4 inverseViewProjection(glm::inverse(projection * view));
    GpuFrame gpu{};
    std::memcpy(gpu.viewProjection, glm::value_ptr(viewProjection), sizeof gpu.viewProjection);
    std::memcpy(gpu.inverseViewProjection, glm::value_ptr(inverseViewProjection),
                sizeof gpu.inverseViewProjection);
    store(gpu.cameraPosition, {camera.position.x, camera.position.y, camera.position.z}, 1.0);
    const glm::dvec3 toLight = glm::normalize(
        glm::dvec3(scene.lightDirection[0], scene.lightDirection[1], scene.lightDirection[2]));
    store(gpu.toLight, {toLight.x, toLight.y, toLight.z}, 0.0);
    store(gpu.lightRadiance, scene.lightRadiance, 0.0);
    store(gpu.ambient, ambientRadiance(scene), textures.environmentLevels());
    store(gpu.viewportSize, {double(frame.width), double(frame.height), 0.0}, 0.0);
    return gpu;
}

Result<Buffer> createFilledBuffer(const Device& device, std::span<const std::byte> bytes,
                                  VkBufferUsageFlags usage) {
    auto buffer =
        Buffer::create(device, std::max<VkDeviceSize>(bytes.size(), 16), usage, MemoryUse::Upload);
    if (!buffer) return buffer;
    std::memcpy(buffer->bytes().data(), bytes.data(), bytes.size());
    return buffer;
}

// Deferred shading in two subpasses. The surface subpass draws the instances with a depth
// test and stores the nearest surface per pixel; the shading subpass shades each covered pixel
// once into the radiance image, which a transfer (or, in the editor, a shader) reads after the
// pass. The surfaces and the depth live only within the pass.
Result<UniqueRenderPass> createRenderPass(VkDevice device) {
    VkAttachmentDescription attachments[3]{};
    VkAttachmentDescription& surfaces = attachments[kSurfaceAttachment];
    surfaces.format = kSurfaceFormat;
    surfaces.samples = VK_SAMPLE_COUNT_1_BIT;
    surfaces.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    surfaces.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    surfaces.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    surfaces.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    surfaces.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    surfaces.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    VkAttachmentDescription& depth = attachments[kDepthAttachment];
    depth = surfaces;
    depth.format = kDepthFormat;
    depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    VkAttachmentDescription& radiance = attachments[kRadianceAttachment];
    radiance = surfaces;
    radiance.format = GpuSceneRenderer::kColorFormat;
    radiance.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    radiance.finalLayout = VK_IMAGE_LAYOUT_GENERAL;  // copied or read by SceneDisplay.comp

    const VkAttachmentReference surfaceOutput{kSurfaceAttachment,
                                              VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference depthWritten{kDepthAttachment,
                                             VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference surfaceInput{kSurfaceAttachment,
                                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkAttachmentReference radianceOutput{kRadianceAttachment,
                                               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpasses[2]{};
    subpasses[0].pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpasses[0].colorAttachmentCount = 1;
    subpasses[0].pColorAttachments = &surfaceOutput;
    subpasses[0].pDepthStencilAttachment = &depthWritten;
    subpasses[1].pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpasses[1].inputAttachmentCount = 1;
    subpasses[1].pInputAttachments = &surfaceInput;
    subpasses[1].colorAttachmentCount = 1;
    subpasses[1].pColorAttachments = &radianceOutput;

    const VkPipelineStageFlags attachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                  VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                  VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    const VkAccessFlags attachmentAccess =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    VkSubpassDependency dependencies[4]{};
    // The previous frame's attachment writes, its input reads and its read of the radiance
    // image come before either subpass touches an attachment.
    for (uint32_t subpass = 0; subpass < 2; ++subpass) {
        VkSubpassDependency& previous = dependencies[subpass];
        previous.srcSubpass = VK_SUBPASS_EXTERNAL;
        previous.dstSubpass = subpass;
        previous.srcStageMask = attachmentStages | VK_PIPELINE_STAGE_TRANSFER_BIT |
                                VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
        previous.srcAccessMask = attachmentAccess;
        previous.dstStageMask = attachmentStages;
        previous.dstAccessMask = attachmentAccess;
    }
    // The shading subpass reads the surfaces the first one wrote.
    VkSubpassDependency& surfacesToShading = dependencies[2];
    surfacesToShading.srcSubpass = 0;
    surfacesToShading.dstSubpass = 1;
    surfacesToShading.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    surfacesToShading.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    surfacesToShading.dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    surfacesToShading.dstAccessMask = VK_ACCESS_INPUT_ATTACHMENT_READ_BIT;
    surfacesToShading.dependencyFlags = VK_DEPENDENCY_BY_REGION_BIT;
    // The radiance image is read by a transfer or the display pass after the pass.
    VkSubpassDependency& radianceOut = dependencies[3];
    radianceOut.srcSubpass = 1;
    radianceOut.dstSubpass = VK_SUBPASS_EXTERNAL;
    radianceOut.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    radianceOut.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    radianceOut.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    radianceOut.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_SHADER_READ_BIT;

    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 3;
    info.pAttachments = attachments;
    info.subpassCount = 2;
    info.pSubpasses = subpasses;
    info.dependencyCount = 4;
    info.pDependencies = dependencies;
    VkRenderPass renderPass = VK_NULL_HANDLE;
    if (VkResult result = vkCreateRenderPass(device, &info, nullptr, &renderPass);
        result != VK_SUCCESS)
        return vulkanError("creating a render pass", result);
    return UniqueRenderPass(device, renderPass);
}

Result<UniquePipeline> createSurfacePipeline(VkDevice device, VkRenderPass renderPass,
                                             VkPipelineLayout layout) {
    const VkVertexInputAttributeDescription attributes[3] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(MeshVertex, position))},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(MeshVertex, normal))},
        {2, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(MeshVertex, uv))},
    };
    GraphicsPipelineSpec spec;
    spec.vertexSpirv = kSceneSurfaceVertexSpirv;
    spec.fragmentSpirv = kSceneSurfaceFragmentSpirv;
    spec.vertexBinding = {0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX};
    spec.vertexAttributes = attributes;
    // The projection's y flip keeps the mesh's counter-clockwise front faces so on screen.
    spec.cullMode = VK_CULL_MODE_BACK_BIT;
    spec.depthTested = true;
    spec.layout = layout;
    spec.renderPass = renderPass;
    spec.subpass = 0;
    spec.name = "scene surface";
    return createGraphicsPipeline(device, spec);
}

// Specialised for the textures and the environment the scene has.
Result<UniquePipeline> createShadingPipeline(VkDevice device, VkRenderPass renderPass,
                                             VkPipelineLayout layout,
                                             const GpuSceneTextures& textures) {
    const uint32_t specialization[2] = {textures.textured() ? 1u : 0u,
                                        textures.environmentLevels() > 0 ? 1u : 0u};
    const SpecializationConstants constants(specialization);
    GraphicsPipelineSpec spec;
    spec.vertexSpirv = kSceneShadeVertexSpirv;
    spec.fragmentSpirv = kSceneShadeFragmentSpirv;
    spec.fragmentSpecialization = constants.info();
    spec.layout = layout;
    spec.renderPass = renderPass;
    spec.subpass = 1;
    spec.name = "scene shading";
    return createGraphicsPipeline(device, spec);
}

}  // namespace

Result<GpuSceneRenderer> GpuSceneRenderer::create(const Device& device, CommandRunner& runner,
                                                  const FgdTables& tables,
                                                  const SceneTextures& textures, const Mesh& mesh) {
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
    auto descriptors =
        DescriptorSet::create(device,
                              {storage, storage, storage, storage, sampled, sampled, sampled,
                               VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT},
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
    auto surfacePipeline =
        createSurfacePipeline(vkDevice, renderer.renderPass_.get(), pipelineLayout);
    if (!surfacePipeline) return surfacePipeline.error();
    renderer.surfacePipeline_ = std::move(surfacePipeline).value();
    auto shadingPipeline = createShadingPipeline(vkDevice, renderer.renderPass_.get(),
                                                 pipelineLayout, renderer.textures_);
    if (!shadingPipeline) return shadingPipeline.error();
    renderer.shadingPipeline_ = std::move(shadingPipeline).value();

    const uint32_t environmentLit = renderer.textures_.environmentLevels() > 0 ? 1u : 0u;
    auto displayKernel = ComputeKernel::create(
        device, kSceneDisplaySpirv,
        {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, storage, sampled, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
        sizeof(DisplayConstants), std::span(&environmentLit, 1));
    if (!displayKernel) return displayKernel.error();
    renderer.displayKernel_ = std::move(displayKernel).value();
    renderer.displayKernel_.bindBuffer(kDisplayFrame, renderer.frameBuffer_);
    renderer.textures_.bindEnvironment(renderer.displayKernel_.descriptors(), kDisplayEnvironment);
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
    GpuImageSpec surfaceSpec;
    surfaceSpec.format = kSurfaceFormat;
    surfaceSpec.extent = extent;
    surfaceSpec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT |
                        VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    GpuImageSpec depthSpec = surfaceSpec;
    depthSpec.format = kDepthFormat;
    depthSpec.usage =
        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    depthSpec.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    GpuImageSpec radianceSpec = surfaceSpec;
    radianceSpec.format = kColorFormat;
    radianceSpec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                         VK_IMAGE_USAGE_STORAGE_BIT;
    auto surfaces = GpuImage::create(*device_, surfaceSpec);
    if (!surfaces) return surfaces.error();
    auto depth = GpuImage::create(*device_, depthSpec);
    if (!depth) return depth.error();
    auto radiance = GpuImage::create(*device_, radianceSpec);
    if (!radiance) return radiance.error();

    VkImageView views[3];
    views[kSurfaceAttachment] = surfaces->view();
    views[kDepthAttachment] = depth->view();
    views[kRadianceAttachment] = radiance->view();
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
    surfaces_ = std::move(surfaces).value();
    depth_ = std::move(depth).value();
    radiance_ = std::move(radiance).value();
    descriptors_.bindInputAttachment(kSurfaces, surfaces_.view());
    displayKernel_.bindStorageImage(kDisplayRadiance, radiance_.view());
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
        auto grown =
            Buffer::create(*device_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload);
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

    VkClearValue clears[3]{};  // surfaces 0: background
    clears[kDepthAttachment].depthStencil = {1.0f, 0};
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
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, surfacePipeline_.get());
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
                             levels_[level].firstIndex, levels_[level].vertexOffset, firstInstance);
        firstInstance += levelInstances_[level];
    }
    vkCmdNextSubpass(commands, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, shadingPipeline_.get());
    vkCmdDraw(commands, 3, 1, 0, 0);  // the full-screen triangle
    vkCmdEndRenderPass(commands);
    return Ok{};
}

Status GpuSceneRenderer::recordDisplay(VkCommandBuffer commands, const GpuImage& target,
                                       const SceneDisplay& display) {
    const VkExtent3D extent = target.spec().extent;
    if (int(extent.width) != width_ || int(extent.height) != height_)
        return Error{"the scene display image is not the frame's size"};
    displayKernel_.bindStorageImage(kDisplayTarget, target.view());
    transitionImage(commands, target.handle(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                    VK_ACCESS_SHADER_WRITE_BIT);
    const DisplayConstants constants{float(std::exp2(display.exposureStops)),
                                     float(kBackdropBlurAlpha),
                                     display.toneMap == ToneMap::Aces ? 1u : 0u};
    displayKernel_.record(commands, &constants, (extent.width + 7) / 8, (extent.height + 7) / 8, 1);
    transitionImage(commands, target.handle(), VK_IMAGE_LAYOUT_GENERAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                    VK_ACCESS_SHADER_WRITE_BIT,
                    VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT);
    return Ok{};
}

Result<Image> GpuSceneRenderer::render(CommandRunner& runner, const SceneFrame& frame,
                                       const SceneSettings& scene,
                                       std::optional<SceneDisplay> display) {
    // Linear radiance is RGBA16F, the displayed picture RGBA32F.
    const VkDeviceSize bytesPerPixel = display ? 16 : 8;
    const VkDeviceSize bytes =
        VkDeviceSize(frame.width) * VkDeviceSize(frame.height) * bytesPerPixel;
    auto readback = Buffer::create(*device_, std::max<VkDeviceSize>(bytes, bytesPerPixel),
                                   VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
    if (!readback) return readback.error();
    auto commands = runner.begin();
    if (!commands) return commands.error();
    if (auto recorded = record(*commands, frame, scene); !recorded) return recorded.error();
    VkImage source = radiance_.handle();
    std::optional<GpuImage> displayed;
    if (!display) {
        transitionImage(*commands, source, VK_IMAGE_LAYOUT_GENERAL,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                        VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    } else {
        GpuImageSpec spec;
        spec.format = VK_FORMAT_R32G32B32A32_SFLOAT;
        spec.extent = {uint32_t(frame.width), uint32_t(frame.height), 1};
        spec.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                     VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        auto created = GpuImage::create(*device_, spec);
        if (!created) return created.error();
        displayed = std::move(created).value();
        if (auto ok = recordDisplay(*commands, *displayed, *display); !ok) return ok.error();
        transitionImage(*commands, displayed->handle(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                        VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        source = displayed->handle();
    }
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {uint32_t(frame.width), uint32_t(frame.height), 1};
    vkCmdCopyImageToBuffer(*commands, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback->handle(), 1, &region);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(*commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                         1, &toHost, 0, nullptr, 0, nullptr);
    if (auto submitted = runner.submitAndWait(); !submitted) return submitted.error();

    Image image(frame.width, frame.height);
    if (display) {
        const auto floats = readback->as<const float>();
        std::copy(floats.begin(), floats.begin() + std::ptrdiff_t(image.rgba.size()),
                  image.rgba.begin());
    } else {
        // (radiance, 1) where a surface was drawn, (0, 0) elsewhere.
        const auto halves = readback->as<const uint16_t>();
        for (std::size_t i = 0; i < image.rgba.size(); ++i)
            image.rgba[i] = glm::unpackHalf1x16(halves[i]);
    }
    return image;
}

}  // namespace matevo::gpu
