#include "gpu/GpuSphereRenderer.h"

#include <cmath>
#include <cstring>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <shaders/kSphereRenderSpirv.h>

#include "gpu/VulkanError.h"

namespace matevo::gpu {
namespace {

constexpr uint32_t kWorkgroupSize = 64;  // local_size_x in the shader

// std430 mirror of the shader's Scene block.
struct GpuScene {
    float cameraPosition[4];
    float cameraForward[4];
    float cameraRight[4];
    float cameraUp[4];
    float toLight[4];
    float lightRadiance[4];
    float environmentRadiance[4];
    float textured[4];  // x: 1 when a texture is present
};

void store(float (&target)[4], const glm::dvec3& xyz, double w) {
    target[0] = float(xyz.x);
    target[1] = float(xyz.y);
    target[2] = float(xyz.z);
    target[3] = float(w);
}

glm::dvec3 toVector(const std::array<double, 3>& values) {
    return {values[0], values[1], values[2]};
}

GpuScene toGpu(const SceneSettings& scene, int size, const GpuSceneTextures& textures) {
    // The camera of core/scene/SphereRenderer.cpp: looks at the origin, +y up.
    const glm::dvec3 position = toVector(scene.cameraPosition);
    const glm::dvec3 forward = glm::normalize(-position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    // The sphere's image is a disc around the image centre (the camera looks at the sphere's
    // centre): the cone of half-angle asin(1 / distance) on the unit image plane, in pixels.
    const double tanHalfFov = std::tan(scene.fieldOfViewDegrees * std::numbers::pi / 360.0);
    const double cameraDistance = glm::length(position);
    // From inside the sphere nothing is seen: a radius of 0 leaves every pixel a miss.
    const double silhouetteAngle = cameraDistance > 1.0 ? std::asin(1.0 / cameraDistance) : 0.0;
    GpuScene gpu{};
    store(gpu.cameraPosition, position, size);
    store(gpu.cameraForward, forward, tanHalfFov);
    store(gpu.cameraRight, right, std::tan(silhouetteAngle) / tanHalfFov * 0.5 * double(size));
    store(gpu.cameraUp, up, 0.0);
    store(gpu.toLight, glm::normalize(toVector(scene.lightDirection)), 0.0);
    store(gpu.lightRadiance, toVector(scene.lightRadiance), 0.0);
    store(gpu.environmentRadiance, toVector(ambientRadiance(scene)),
          textures.environmentLevels());
    store(gpu.textured, {textures.textured() ? 1.0 : 0.0, 0.0, 0.0}, 0.0);
    return gpu;
}

}  // namespace

Result<GpuSphereRenderer> GpuSphereRenderer::create(const Device& device, CommandRunner& runner,
                                                    const FgdTables& tables,
                                                    const SceneTextures& textures) {
    GpuSphereRenderer renderer;
    renderer.device_ = &device;
    renderer.tables_ = &tables;
    auto uploaded = GpuSceneTextures::create(device, runner, textures);
    if (!uploaded) return uploaded.error();
    auto sceneBuffer = Buffer::create(device, sizeof(GpuScene), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                      MemoryUse::Upload);
    if (!sceneBuffer) return sceneBuffer.error();

    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    auto kernel = ComputeKernel::create(
        device, kSphereRenderSpirv,
        {storage, storage, sampled, sampled, storage, storage, sampled}, 0);
    if (!kernel) return kernel.error();

    renderer.textures_ = std::move(uploaded).value();
    renderer.sceneBuffer_ = std::move(sceneBuffer).value();
    renderer.kernel_ = std::move(kernel).value();
    renderer.textures_.bind(renderer.kernel_.descriptors(), 2, 3, 6);
    renderer.kernel_.bindBuffer(4, renderer.sceneBuffer_);
    return renderer;
}

Status GpuSphereRenderer::record(VkCommandBuffer commands,
                                 std::span<const MaterialInstance> materials,
                                 const SceneSettings& scene, int size, const Buffer& renders) {
    if (auto uploaded = materials_.upload(*device_, *tables_, materials); !uploaded)
        return uploaded.error();
    const GpuScene gpuScene = toGpu(scene, size, textures_);
    std::memcpy(sceneBuffer_.bytes().data(), &gpuScene, sizeof(gpuScene));

    kernel_.bindBuffer(0, materials_.materials());
    kernel_.bindBuffer(1, renders);
    kernel_.bindBuffer(5, materials_.lobeEntries());
    const uint32_t pixelCount = uint32_t(size) * uint32_t(size);
    kernel_.record(commands, nullptr, (pixelCount + kWorkgroupSize - 1) / kWorkgroupSize,
                   uint32_t(materials.size()), 1);
    return Ok{};
}

Result<std::vector<Image>> GpuSphereRenderer::render(CommandRunner& runner,
                                                     std::span<const MaterialInstance> materials,
                                                     const SceneSettings& scene, int size) {
    const ImageBatchShape shape{size, size, uint32_t(materials.size())};
    if (materials.empty() || size <= 0) return std::vector<Image>{};
    auto renders = createBatchBuffer(*device_, shape, 4, MemoryUse::Readback);
    if (!renders) return renders.error();
    auto commands = runner.begin();
    if (!commands) return commands.error();
    if (auto recorded = record(*commands, materials, scene, size, *renders); !recorded)
        return recorded.error();
    computeWriteToHostReadBarrier(*commands);
    if (auto submitted = runner.submitAndWait(); !submitted) return submitted.error();
    std::vector<Image> images;
    for (uint32_t i = 0; i < shape.count; ++i) images.push_back(downloadImage(*renders, shape, i));
    return images;
}

}  // namespace matevo::gpu
