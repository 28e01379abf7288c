#include "gpu/GpuSphereRenderer.h"

#include <cstring>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include <shaders/kSphereRenderComparedSpirv.h>
#include <shaders/kSphereRenderSpirv.h>

#include "gpu/VulkanError.h"
#include "scene/SphereSamples.h"

namespace matevo::gpu {
namespace {

constexpr uint32_t kWorkgroupSize = 64;  // local_size_x in the shader

// std140 mirror of the shader's Scene block (three vec4: the same in both layouts).
struct GpuScene {
    float toLight[4];
    float lightRadiance[4];
    float environmentRadiance[4];
};

// The shader's push constants: which covered pixels one dispatch shades.
struct PushConstants {
    uint32_t pixelsPerImage;
    uint32_t firstPixel;
    uint32_t pixelCount;
};

void store(float (&target)[4], const std::array<double, 3>& xyz, double w) {
    for (int i = 0; i < 3; ++i) target[i] = float(xyz[std::size_t(i)]);
    target[3] = float(w);
}

GpuScene toGpu(const SceneSettings& scene, const GpuSceneTextures& textures) {
    const glm::dvec3 toLight = glm::normalize(
        glm::dvec3(scene.lightDirection[0], scene.lightDirection[1], scene.lightDirection[2]));
    GpuScene gpu{};
    store(gpu.toLight, {toLight.x, toLight.y, toLight.z}, 0.0);
    store(gpu.lightRadiance, scene.lightRadiance, 0.0);
    store(gpu.environmentRadiance, ambientRadiance(scene), textures.environmentLevels());
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
    auto sceneBuffer = Buffer::create(device, sizeof(GpuScene), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                      MemoryUse::Upload);
    if (!sceneBuffer) return sceneBuffer.error();

    renderer.textures_ = std::move(uploaded).value();
    renderer.sceneBuffer_ = std::move(sceneBuffer).value();
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    for (bool compared : {false, true}) {
        const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
        const VkDescriptorType uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        std::vector<VkDescriptorType> bindings = {texels, storage, sampled, sampled, uniform,
                                                  texels, sampled, texels,  texels};
        // The target's L*a*b* and the ΔE00 maps.
        if (compared) bindings.insert(bindings.end(), {texels, storage});
        // One pipeline for the pixels of one point, one for the silhouette's of several.
        for (bool silhouette : {false, true}) {
            const uint32_t specialization[] = {renderer.textures_.textured() ? 1u : 0u,
                                               renderer.textures_.environmentLevels() > 0 ? 1u : 0u,
                                               uint32_t(silhouette ? kMaxPointsPerPixel : 1)};
            auto kernel = ComputeKernel::create(
                device,
                compared ? std::span<const uint32_t>(kSphereRenderComparedSpirv)
                         : std::span<const uint32_t>(kSphereRenderSpirv),
                bindings, sizeof(PushConstants), specialization);
            if (!kernel) return kernel.error();
            renderer.textures_.bind(kernel->descriptors(), 2, 3, 6);
            kernel->bindBuffer(4, renderer.sceneBuffer_);
            renderer.kernels_[compared][silhouette] = std::move(kernel).value();
        }
    }
    return renderer;
}

Status GpuSphereRenderer::record(VkCommandBuffer commands,
                                 std::span<const MaterialInstance> materials,
                                 const SceneSettings& scene, int size, const Buffer& renders,
                                 const TargetComparison* comparison, bool backgroundFilled) {
    if (auto uploaded = materials_.upload(*device_, *tables_, materials); !uploaded)
        return uploaded.error();
    if (auto prepared = samples_.prepare(*device_, scene, size); !prepared) return prepared.error();
    const GpuScene gpuScene = toGpu(scene, textures_);
    std::memcpy(sceneBuffer_.bytes().data(), &gpuScene, sizeof(gpuScene));

    const ImageBatchShape shape{size, size, uint32_t(materials.size())};
    // The shader writes covered pixels only. (On lavapipe a fill is a memset on the queue's
    // thread: a 64-candidate grid's two buffers take about 20 MB of it.)
    if (!backgroundFilled) {
        recordClear(commands, renders, shape, 4, 0.0f);
        if (comparison) {
            recordClear(commands, *comparison->deltaE, shape, 1, -1.0f);
        }
    } else {
        recordRewrite(commands);
    }
    const uint32_t singlePoint = samples_.singlePointPixels();
    const uint32_t silhouette = samples_.coveredPixels() - singlePoint;
    for (auto [silhouettePixels, first, count] :
         {std::tuple{false, 0u, singlePoint}, std::tuple{true, singlePoint, silhouette}}) {
        const ComputeKernel& kernel = kernels_[comparison != nullptr][silhouettePixels];
        kernel.descriptors().bindTexelBuffer(0, materials_.materials());
        kernel.bindBuffer(1, renders);
        kernel.descriptors().bindTexelBuffer(5, materials_.lobeEntries());
        kernel.descriptors().bindTexelBuffer(7, samples_.pixels());
        kernel.descriptors().bindTexelBuffer(8, samples_.points());
        const PushConstants constants{shape.pixelCount(), first, count};
        if (comparison) {
            kernel.descriptors().bindTexelBuffer(9, comparison->targetLab);
            kernel.bindBuffer(10, *comparison->deltaE);
        }
        if (count > 0)
            kernel.record(commands, &constants, (count + kWorkgroupSize - 1) / kWorkgroupSize,
                          shape.count, 1);
    }
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
