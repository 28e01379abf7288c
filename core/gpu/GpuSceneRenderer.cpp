#include "gpu/GpuSceneRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <shaders/kSceneDisplaySpirv.h>
#include <shaders/kSceneRasterizeSpirv.h>
#include <shaders/kSceneShadeAttachmentsFragmentSpirv.h>
#include <shaders/kSceneShadeFragmentSpirv.h>
#include <shaders/kSceneShadeVertexSpirv.h>

#include "gpu/GraphicsPipeline.h"
#include "gpu/ShaderModule.h"
#include "gpu/VulkanObjects.h"
#include "mesh/MeshClusters.h"
#include "scene/EnvironmentBackdrop.h"

namespace matevo::gpu {
namespace {

// The shading pass's descriptor set (SceneShade.frag). kVisibility is the compute pass's
// words or the raster pass's triangle attachment, kDepths (raster pass only) its depth buffer.
enum Binding : uint32_t {
    kInstances = 0,
    kFrame = 1,
    kLobeEntries = 2,
    kMaterials = 3,
    kRoughness = 4,
    kBaseColor = 5,
    kEnvironment = 6,
    kVisibility = 7,
    kVertices = 8,
    kTriangles = 9,
    kClusters = 10,
    kDepths = 11,
};

// The visibility pass's (SceneRasterize.comp) bindings and push constants.
enum RasterizeBinding : uint32_t {
    kRasterizeVertices = 0,
    kRasterizeTriangles = 1,
    kRasterizeClusters = 2,
    kRasterizeVisibility = 3,
};

struct RasterizeConstants {
    float clipFromObject[16];
    float viewportSize[2];
    uint32_t firstEntry;
    uint32_t entries;
    uint32_t triangleCount;
};

// Texel formats of the buffers both passes read (shaders/SceneVisibility.glsl).
constexpr VkFormat kInstanceTexel = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat kVertexTexel = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat kTriangleTexel = VK_FORMAT_R32G32B32A32_UINT;
constexpr VkFormat kClusterTexel = VK_FORMAT_R32G32_UINT;
// Two samples' (triangle, depth bits) per texel.
constexpr VkFormat kVisibilityTexel = VK_FORMAT_R32G32B32A32_UINT;
// Visibility samples per pixel, at the standard 4x multisample positions
// (shaders/SceneVisibility.glsl).
constexpr VkDeviceSize kSamplesPerPixel = 4;

// Work groups of the visibility pass per row of its dispatch (a dispatch has at most 65535
// groups per dimension).
constexpr uint32_t kClusterGroupsPerRow = 1024;

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

// std430 mirrors of the shaders' blocks.
struct GpuInstance {
    float transform[16];
    float material[4];  // x: the index, exact as a float
};

struct GpuFrame {
    float viewProjection[16];
    float inverseViewProjection[16];
    float cameraPosition[4];
    float toLight[4];
    float lightRadiance[4];
    float ambient[4];  // w: environment levels
    float viewportSize[4];
    float sampling[4];  // x: (far - near) / far; y: a pixel's width at unit distance
};

void store(float (&target)[4], const std::array<double, 3>& xyz, double w) {
    for (int c = 0; c < 3; ++c) target[c] = float(xyz[std::size_t(c)]);
    target[3] = float(w);
}

// Depth range [0, 1]; the near plane close enough for a camera inside the crowd.
constexpr double kNearPlane = 0.05;
constexpr double kFarPlane = 1000.0;

double fieldOfViewRadians(const SceneCamera& camera) {
    return camera.fieldOfViewDegrees * std::numbers::pi / 180.0;
}

glm::dmat4 viewProjectionOf(const SceneFrame& frame) {
    const SceneCamera& camera = frame.camera;
    const glm::dmat4 view = glm::lookAt(camera.position, camera.target, glm::dvec3(0, 1, 0));
    glm::dmat4 projection =
        glm::perspectiveRH_ZO(fieldOfViewRadians(camera),
                              double(frame.width) / double(frame.height), kNearPlane, kFarPlane);
    projection[1][1] *= -1.0;  // Vulkan's framebuffer y points down
    return projection * view;
}

// True when no point within `radius` of `center` is inside the view's frustum (clip space
// -w <= x, y <= w, 0 <= z <= w): the sphere lies wholly outside one of its planes.
bool outsideFrustum(const glm::dmat4& viewProjection, const glm::dvec3& center, double radius) {
    const glm::dmat4 rows = glm::transpose(viewProjection);
    const glm::dvec4 planes[6] = {rows[3] + rows[0], rows[3] - rows[0], rows[3] + rows[1],
                                  rows[3] - rows[1], rows[2],           rows[3] - rows[2]};
    for (const glm::dvec4& plane : planes) {
        const double normalLength = glm::length(glm::dvec3(plane));
        if (glm::dot(glm::dvec3(plane), center) + plane.w < -radius * normalLength) return true;
    }
    return false;
}

GpuFrame toGpu(const SceneFrame& frame, const SceneSettings& scene,
               const GpuSceneTextures& textures) {
    const SceneCamera& camera = frame.camera;
    const glm::dmat4 viewProjectionD = viewProjectionOf(frame);
    const glm::mat4 viewProjection(viewProjectionD);
    const glm::mat4 inverseViewProjection(glm::inverse(viewProjectionD));
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
    store(gpu.sampling,
          {(kFarPlane - kNearPlane) / kFarPlane,
           2.0 * std::tan(fieldOfViewRadians(camera) / 2.0) / double(frame.height), 0.0},
          0.0);
    return gpu;
}

// The shading pass: one subpass that shades each covered pixel into the radiance image, which
// a transfer (or, in the editor, a shader) reads after the pass.
Result<UniqueRenderPass> createShadingRenderPass(VkDevice device) {
    VkAttachmentDescription radiance{};
    radiance.format = GpuSceneRenderer::kColorFormat;
    radiance.samples = VK_SAMPLE_COUNT_1_BIT;
    radiance.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    radiance.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    radiance.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    radiance.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    radiance.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    radiance.finalLayout = VK_IMAGE_LAYOUT_GENERAL;  // copied or read by SceneDisplay.comp
    const VkAttachmentReference radianceOutput{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &radianceOutput;

    VkSubpassDependency dependencies[2]{};
    // The previous frame's reads of the radiance image (a copy or the display pass) come
    // before this frame writes it; the visibility pass's words before the shader reads them.
    VkSubpassDependency& previous = dependencies[0];
    previous.srcSubpass = VK_SUBPASS_EXTERNAL;
    previous.dstSubpass = 0;
    previous.srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    previous.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    previous.dstStageMask =
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    previous.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                             VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_SHADER_READ_BIT;
    // The radiance image is read by a transfer or the display pass after the pass.
    VkSubpassDependency& radianceOut = dependencies[1];
    radianceOut.srcSubpass = 0;
    radianceOut.dstSubpass = VK_SUBPASS_EXTERNAL;
    radianceOut.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    radianceOut.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    radianceOut.dstStageMask =
        VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    radianceOut.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_SHADER_READ_BIT;

    return createRenderPass(device, std::span(&radiance, 1), subpass, dependencies);
}

// Specialised for the textures and the environment the scene has; reading the samples of the
// given visibility pass.
Result<UniquePipeline> createShadingPipeline(VkDevice device, VkRenderPass renderPass,
                                             VkPipelineLayout layout,
                                             const GpuSceneTextures& textures,
                                             SceneVisibilityPass visibility) {
    const uint32_t specialization[2] = {textures.textured() ? 1u : 0u,
                                        textures.environmentLevels() > 0 ? 1u : 0u};
    const SpecializationConstants constants(specialization);
    GraphicsPipelineSpec spec;
    spec.vertexSpirv = kSceneShadeVertexSpirv;
    spec.fragmentSpirv = visibility == SceneVisibilityPass::Raster
                             ? std::span<const uint32_t>(kSceneShadeAttachmentsFragmentSpirv)
                             : std::span<const uint32_t>(kSceneShadeFragmentSpirv);
    spec.fragmentSpecialization = constants.info();
    spec.layout = layout;
    spec.renderPass = renderPass;
    spec.name = "scene shading";
    return createGraphicsPipeline(device, spec);
}

// Auto: the compute pass on a CPU device (lavapipe runs the fixed-function front end on one
// thread, the compute pass on all of them) or on a GPU that cannot run the raster pass; the
// raster pass on a GPU (docs/scene-view.md).
SceneVisibilityPass resolve(const Device& device, SceneVisibilityPass requested) {
    if (requested != SceneVisibilityPass::Auto) return requested;
    return device.isCpu() || !SceneRasterVisibility::supportedOn(device)
               ? SceneVisibilityPass::Compute
               : SceneVisibilityPass::Raster;
}

}  // namespace

Result<GpuSceneRenderer> GpuSceneRenderer::create(const Device& device, CommandRunner& runner,
                                                  const FgdTables& tables,
                                                  const SceneTextures& textures, const Mesh& mesh,
                                                  SceneVisibilityPass visibility,
                                                  FillPath meshFill) {
    const VkDevice vkDevice = device.handle();
    GpuSceneRenderer renderer;
    renderer.device_ = &device;
    renderer.tables_ = &tables;
    renderer.visibilityPass_ = resolve(device, visibility);
    const bool raster = renderer.visibilityPass_ == SceneVisibilityPass::Raster;
    if (!raster && !device.int64Atomics())
        return environmentError(
            "Vulkan: " + device.name() +
            " lacks 64-bit integer atomics on storage buffers, which the scene's "
            "compute visibility pass needs");
    auto uploaded = GpuSceneTextures::create(device, runner, textures);
    if (!uploaded) return uploaded.error();
    renderer.textures_ = std::move(uploaded).value();

    // The mesh's triangles in clusters (core/mesh/MeshClusters.h), read by every pass.
    ClusteredMesh clustered = clusterTriangles(mesh);
    renderer.triangleCount_ = uint32_t(clustered.mesh.triangleCount());
    renderer.clusters_ = std::move(clustered.clusters);
    std::vector<glm::uvec4> triangles(renderer.triangleCount_);
    for (std::size_t t = 0; t < triangles.size(); ++t)
        triangles[t] = {clustered.mesh.indices[t * 3], clustered.mesh.indices[t * 3 + 1],
                        clustered.mesh.indices[t * 3 + 2], 0u};
    const VkBufferUsageFlags texelUsage = VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    auto vertices =
        Buffer::createFilled(device, runner, std::as_bytes(std::span(clustered.mesh.vertices)),
                             texelUsage | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, meshFill);
    if (!vertices) return vertices.error();
    auto triangleBuffer = Buffer::createFilled(device, runner, std::as_bytes(std::span(triangles)),
                                               texelUsage, meshFill);
    if (!triangleBuffer) return triangleBuffer.error();
    auto verticesView = createTexelView(device, *vertices, kVertexTexel);
    if (!verticesView) return verticesView.error();
    auto trianglesView = createTexelView(device, *triangleBuffer, kTriangleTexel);
    if (!trianglesView) return trianglesView.error();
    auto frameBuffer = Buffer::create(device, sizeof(GpuFrame), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                      MemoryUse::Upload);
    if (!frameBuffer) return frameBuffer.error();
    renderer.vertices_ = std::move(vertices).value();
    renderer.triangles_ = std::move(triangleBuffer).value();
    renderer.verticesView_ = std::move(verticesView).value();
    renderer.trianglesView_ = std::move(trianglesView).value();
    renderer.frameBuffer_ = std::move(frameBuffer).value();

    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    const VkDescriptorType attachment = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    std::vector<VkDescriptorType> shadingBindings = {
        texels, storage, texels, texels, sampled, sampled, sampled, raster ? attachment : texels,
        texels, texels,  texels};
    if (raster) shadingBindings.push_back(attachment);  // kDepths
    auto descriptors =
        DescriptorSet::create(device, std::move(shadingBindings), VK_SHADER_STAGE_FRAGMENT_BIT);
    if (!descriptors) return descriptors.error();
    renderer.descriptors_ = std::move(descriptors).value();
    renderer.descriptors_.bindBuffer(kFrame, renderer.frameBuffer_);
    renderer.descriptors_.bindTexelBuffer(kVertices, renderer.verticesView_.get());
    renderer.descriptors_.bindTexelBuffer(kTriangles, renderer.trianglesView_.get());
    renderer.textures_.bind(renderer.descriptors_, kRoughness, kBaseColor, kEnvironment);

    if (raster) {
        auto rasterVisibility = SceneRasterVisibility::create(
            device, runner, renderer.vertices_.handle(), clustered.mesh.indices, meshFill);
        if (!rasterVisibility) return rasterVisibility.error();
        renderer.rasterVisibility_ = std::move(rasterVisibility).value();
    } else {
        auto rasterizeKernel =
            ComputeKernel::create(device, kSceneRasterizeSpirv, {texels, texels, texels, storage},
                                  sizeof(RasterizeConstants));
        if (!rasterizeKernel) return rasterizeKernel.error();
        renderer.rasterizeKernel_ = std::move(rasterizeKernel).value();
        const DescriptorSet& rasterizeSet = renderer.rasterizeKernel_.descriptors();
        rasterizeSet.bindTexelBuffer(kRasterizeVertices, renderer.verticesView_.get());
        rasterizeSet.bindTexelBuffer(kRasterizeTriangles, renderer.trianglesView_.get());
    }

    auto renderPass = createShadingRenderPass(vkDevice);
    if (!renderPass) return renderPass.error();
    renderer.renderPass_ = std::move(renderPass).value();
    auto pipelineLayout = createPipelineLayout(vkDevice, renderer.descriptors_.layout());
    if (!pipelineLayout) return pipelineLayout.error();
    renderer.pipelineLayout_ = std::move(pipelineLayout).value();
    auto shadingPipeline =
        createShadingPipeline(vkDevice, renderer.renderPass_.get(), renderer.pipelineLayout_.get(),
                              renderer.textures_, renderer.visibilityPass_);
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
    if (materials.empty()) return internalError("the scene needs at least one material");
    if (auto uploaded = materials_.upload(*device_, *tables_, materials); !uploaded)
        return uploaded.error();
    materialCount_ = uint32_t(materials.size());
    descriptors_.bindTexelBuffer(kMaterials, materials_.materials());
    descriptors_.bindTexelBuffer(kLobeEntries, materials_.lobeEntries());
    return Ok{};
}

Status GpuSceneRenderer::prepareTarget(int width, int height) {
    if (width == width_ && height == height_) return Ok{};
    GpuImageSpec radianceSpec;
    radianceSpec.format = kColorFormat;
    radianceSpec.extent = {uint32_t(width), uint32_t(height), 1};
    radianceSpec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                         VK_IMAGE_USAGE_STORAGE_BIT;
    auto radiance = GpuImage::create(*device_, radianceSpec);
    if (!radiance) return radiance.error();
    if (rasterVisibility_) {
        if (auto ok = rasterVisibility_->prepareTarget(width, height); !ok) return ok.error();
        descriptors_.bindSampledImage(kVisibility, rasterVisibility_->surfaces(), VK_NULL_HANDLE);
        descriptors_.bindSampledImage(kDepths, rasterVisibility_->depths(), VK_NULL_HANDLE);
    } else {
        // One 64-bit visibility word per sample.
        auto visibility = Buffer::create(
            *device_,
            VkDeviceSize(width) * VkDeviceSize(height) * kSamplesPerPixel * sizeof(uint64_t),
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT |
                VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            MemoryUse::DeviceLocal);
        if (!visibility) return visibility.error();
        auto visibilityView = createTexelView(*device_, *visibility, kVisibilityTexel);
        if (!visibilityView) return visibilityView.error();
        visibility_ = std::move(visibility).value();
        visibilityView_ = std::move(visibilityView).value();
        descriptors_.bindTexelBuffer(kVisibility, visibilityView_.get());
        rasterizeKernel_.bindBuffer(kRasterizeVisibility, visibility_);
    }

    const VkImageView view = radiance->view();
    auto framebuffer = createFramebuffer(device_->handle(), renderPass_.get(), std::span(&view, 1),
                                         uint32_t(width), uint32_t(height));
    if (!framebuffer) return framebuffer.error();
    framebuffer_ = std::move(framebuffer).value();
    radiance_ = std::move(radiance).value();
    displayKernel_.bindStorageImage(kDisplayRadiance, radiance_.view());
    width_ = width;
    height_ = height;
    return Ok{};
}

Status GpuSceneRenderer::prepareInstances(const SceneFrame& frame) {
    const std::span<const SceneInstance> instances = frame.instances;
    const glm::dmat4 viewProjection = viewProjectionOf(frame);
    std::vector<GpuInstance> gpuInstances(std::max<std::size_t>(instances.size(), 1));
    std::vector<glm::uvec2> entries;  // (instance, cluster)
    instanceWork_.clear();
    const bool cullClusters = frame.cullClusters && visibilityPass_ == SceneVisibilityPass::Compute;
    for (std::size_t i = 0; i < instances.size(); ++i) {
        const SceneInstance& instance = instances[i];
        if (instance.material >= materialCount_)
            return internalError("scene instance " + std::to_string(i) + " names material " +
                                 std::to_string(instance.material) + " of " +
                                 std::to_string(materialCount_));
        GpuInstance& gpu = gpuInstances[i];
        std::memcpy(gpu.transform, glm::value_ptr(instance.transform), sizeof gpu.transform);
        gpu.material[0] = float(instance.material);
        // Meshes fit the unit sphere (core/mesh/Mesh.h).
        const double scale = glm::length(glm::dvec3(instance.transform[0]));
        if (outsideFrustum(viewProjection, glm::dvec3(instance.transform[3]), scale)) continue;
        const std::size_t firstEntry = entries.size();
        // The raster pass names a triangle by its instance's first entry plus its index in the
        // mesh (SceneSurfaces.frag), so its instances keep every cluster, in order.
        for (std::size_t c = 0; c < clusters_.size(); ++c)
            if (!cullClusters ||
                !facesAwayFrom(clusters_[c], instance.transform, frame.camera.position))
                entries.push_back({uint32_t(i), uint32_t(c)});
        if (entries.size() > firstEntry)
            instanceWork_.push_back({glm::mat4(viewProjection * glm::dmat4(instance.transform)),
                                     uint32_t(firstEntry), uint32_t(entries.size() - firstEntry)});
    }
    if (entries.size() > std::numeric_limits<uint32_t>::max() / kClusterTriangles)
        return badInput("the scene has too many instances of too large a mesh (" +
                        std::to_string(entries.size()) + " clusters in view)");
    trianglesSubmitted_ = 0;
    for (const glm::uvec2& entry : entries)
        trianglesSubmitted_ += std::min<uint64_t>(
            kClusterTriangles, triangleCount_ - uint64_t(entry.y) * kClusterTriangles);
    if (auto ok = upload(instances_, std::as_bytes(std::span(gpuInstances)), kInstanceTexel,
                         kInstances, std::nullopt);
        !ok)
        return ok;
    if (entries.empty()) entries.push_back({0, 0});  // a buffer is never empty
    return upload(visibleClusters_, std::as_bytes(std::span(entries)), kClusterTexel, kClusters,
                  kRasterizeClusters);
}

Status GpuSceneRenderer::upload(TexelBuffer& target, std::span<const std::byte> bytes,
                                VkFormat format, uint32_t shadingBinding,
                                std::optional<uint32_t> rasterizeBinding) {
    Buffer& buffer = target.buffer;
    if (buffer.size() < bytes.size()) {
        auto grown = Buffer::create(*device_, bytes.size(),
                                    VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, MemoryUse::Upload);
        if (!grown) return grown.error();
        auto view = createTexelView(*device_, *grown, format);
        if (!view) return view.error();
        buffer = std::move(grown).value();
        target.view = std::move(view).value();
        descriptors_.bindTexelBuffer(shadingBinding, target.view.get());
        if (rasterizeBinding && !rasterVisibility_)
            rasterizeKernel_.descriptors().bindTexelBuffer(*rasterizeBinding, target.view.get());
    }
    std::memcpy(buffer.bytes().data(), bytes.data(), bytes.size());
    return Ok{};
}

Status GpuSceneRenderer::record(VkCommandBuffer commands, const SceneFrame& frame,
                                const SceneSettings& scene) {
    if (frame.width <= 0 || frame.height <= 0) return internalError("the scene image is empty");
    if (materialCount_ == 0) return internalError("the scene has no materials (setMaterials)");
    if (auto ok = prepareTarget(frame.width, frame.height); !ok) return ok.error();
    if (auto ok = prepareInstances(frame); !ok) return ok.error();
    const GpuFrame gpuFrame = toGpu(frame, scene, textures_);
    std::memcpy(frameBuffer_.bytes().data(), &gpuFrame, sizeof gpuFrame);

    if (auto ok = rasterVisibility_ ? recordRasterVisibility(commands)
                                    : recordComputeVisibility(commands, frame);
        !ok)
        return ok.error();

    // The shading pass (its subpass dependency, or the raster pass's, orders it after the
    // visibility pass).
    VkClearValue clear{};  // transparent background
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = renderPass_.get();
    begin.framebuffer = framebuffer_.get();
    begin.renderArea = {{0, 0}, {uint32_t(frame.width), uint32_t(frame.height)}};
    begin.clearValueCount = 1;
    begin.pClearValues = &clear;
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    const VkViewport viewport{0.0f, 0.0f, float(frame.width), float(frame.height), 0.0f, 1.0f};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &begin.renderArea);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, shadingPipeline_.get());
    const VkDescriptorSet set = descriptors_.handle();
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_.get(), 0, 1,
                            &set, 0, nullptr);
    vkCmdDraw(commands, 3, 1, 0, 0);  // the full-screen triangle
    vkCmdEndRenderPass(commands);
    return Ok{};
}

Status GpuSceneRenderer::recordComputeVisibility(VkCommandBuffer commands,
                                                 const SceneFrame& frame) {
    // Every word to "no surface" (after the previous frame's shading read
    // them), then the nearest surface of each pixel.
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = 0;
    barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
    vkCmdFillBuffer(commands, visibility_.handle(), 0, VK_WHOLE_SIZE, 0xffffffffu);
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0,
                         nullptr);
    for (const InstanceWork& work : instanceWork_) {
        RasterizeConstants constants{{},
                                     {float(frame.width), float(frame.height)},
                                     work.firstEntry,
                                     work.entries,
                                     triangleCount_};
        std::memcpy(constants.clipFromObject, glm::value_ptr(work.clipFromObject),
                    sizeof constants.clipFromObject);
        const uint32_t groupsX = std::min(work.entries, kClusterGroupsPerRow);
        rasterizeKernel_.record(commands, &constants, groupsX,
                                (work.entries + groupsX - 1) / groupsX, 1);
    }
    return Ok{};
}

Status GpuSceneRenderer::recordRasterVisibility(VkCommandBuffer commands) {
    std::vector<SceneRasterVisibility::DrawnInstance> drawn(instanceWork_.size());
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        drawn[i].clipFromObject = instanceWork_[i].clipFromObject;
        drawn[i].firstSurface = instanceWork_[i].firstEntry * kClusterTriangles;
    }
    return rasterVisibility_->record(commands, drawn);
}

Status GpuSceneRenderer::recordDisplay(VkCommandBuffer commands, const GpuImage& target,
                                       const SceneDisplay& display) {
    const VkExtent3D extent = target.spec().extent;
    if (int(extent.width) != width_ || int(extent.height) != height_)
        return internalError("the scene display image is not the frame's size");
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
        // (radiance, the share of the samples covered); (0, 0) where no surface was drawn.
        const auto halves = readback->as<const uint16_t>();
        for (std::size_t i = 0; i < image.rgba.size(); ++i)
            image.rgba[i] = glm::unpackHalf1x16(halves[i]);
    }
    return image;
}

}  // namespace matevo::gpu
