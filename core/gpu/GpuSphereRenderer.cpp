#include "gpu/GpuSphereRenderer.h"

#include <cmath>
#include <cstring>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <shaders/kSphereRenderSpirv.h>

#include "gpu/VulkanError.h"
#include "material/LobeTable.h"
#include "material/ParallelFor.h"

namespace matevo::gpu {
namespace {

constexpr uint32_t kWorkgroupSize = 64;  // local_size_x in the shader

// std430 mirrors of the shader's blocks.
struct GpuMaterial {
    uint32_t firstEntry;  // of its lobe table, in entries
    uint32_t texelNodes;
    uint32_t cosineNodes;
    uint32_t unused;
};

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

GpuScene toGpu(const SceneSettings& scene, int size, bool textured) {
    // The camera of core/scene/SphereRenderer.cpp: looks at the origin, +y up.
    const glm::dvec3 position = toVector(scene.cameraPosition);
    const glm::dvec3 forward = glm::normalize(-position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    GpuScene gpu{};
    store(gpu.cameraPosition, position, size);
    store(gpu.cameraForward, forward,
          std::tan(scene.fieldOfViewDegrees * std::numbers::pi / 360.0));
    store(gpu.cameraRight, right, 0.0);
    store(gpu.cameraUp, up, 0.0);
    store(gpu.toLight, glm::normalize(toVector(scene.lightDirection)), 0.0);
    store(gpu.lightRadiance, toVector(scene.lightRadiance), 0.0);
    store(gpu.environmentRadiance, toVector(ambientRadiance(scene)), 0.0);
    store(gpu.textured, {textured ? 1.0 : 0.0, 0.0, 0.0}, 0.0);
    return gpu;
}

Status requireLinearSampling(const Device& device, VkFormat format, const char* what) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device.physicalDevice(), format, &properties);
    const VkFormatFeatureFlags needed =
        VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
    if ((properties.optimalTilingFeatures & needed) != needed)
        return Error{std::string("Vulkan: ") + device.name() + " cannot filter " + what +
                     " linearly"};
    return Ok{};
}

Result<UniqueSampler> createSampler(const Device& device, VkSamplerAddressMode u,
                                    VkSamplerAddressMode otherAxes) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = VK_FILTER_LINEAR;
    info.minFilter = VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = u;
    info.addressModeV = otherAxes;
    info.addressModeW = otherAxes;
    info.maxLod = 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    if (VkResult result = vkCreateSampler(device.handle(), &info, nullptr, &sampler);
        result != VK_SUCCESS)
        return vulkanError("creating a sampler", result);
    return UniqueSampler(device.handle(), sampler);
}

// An RGBA float texture from an image; a 1x1 white one (the neutral texel) for an empty image.
Result<GpuImage> uploadTexture(const Device& device, CommandRunner& runner, const Image& image) {
    const Image white = [] {
        Image texel(1, 1);
        texel.rgba = {1.0f, 1.0f, 1.0f, 1.0f};
        return texel;
    }();
    const Image& source = image.width > 0 ? image : white;
    GpuImageSpec spec;
    spec.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    spec.extent = {uint32_t(source.width), uint32_t(source.height), 1};
    return GpuImage::createFilled(device, runner, spec, std::as_bytes(std::span(source.rgba)));
}

}  // namespace

Result<GpuSphereRenderer> GpuSphereRenderer::create(const Device& device, CommandRunner& runner,
                                                    const FgdTables& tables,
                                                    const SceneTextures& textures) {
    if (auto ok = requireLinearSampling(device, VK_FORMAT_R32G32B32A32_SFLOAT,
                                        "R32G32B32A32_SFLOAT textures");
        !ok)
        return ok.error();

    GpuSphereRenderer renderer;
    renderer.device_ = &device;
    renderer.tables_ = &tables;
    renderer.textured_ = textures.roughness.width > 0 || textures.baseColor.width > 0;
    auto roughness = uploadTexture(device, runner, textures.roughness);
    if (!roughness) return roughness.error();
    auto baseColor = uploadTexture(device, runner, textures.baseColor);
    if (!baseColor) return baseColor.error();
    auto textureSampler = createSampler(device, VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
    if (!textureSampler) return textureSampler.error();
    auto sceneBuffer = Buffer::create(device, sizeof(GpuScene), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                      MemoryUse::Upload);
    if (!sceneBuffer) return sceneBuffer.error();

    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    auto kernel = ComputeKernel::create(device, kSphereRenderSpirv,
                                        {storage, storage, sampled, sampled, storage, storage}, 0);
    if (!kernel) return kernel.error();

    renderer.roughness_ = std::move(roughness).value();
    renderer.baseColor_ = std::move(baseColor).value();
    renderer.textureSampler_ = std::move(textureSampler).value();
    renderer.sceneBuffer_ = std::move(sceneBuffer).value();
    renderer.kernel_ = std::move(kernel).value();
    const ComputeKernel& bound = renderer.kernel_;
    bound.bindSampledImage(2, renderer.roughness_.view(), renderer.textureSampler_.get());
    bound.bindSampledImage(3, renderer.baseColor_.view(), renderer.textureSampler_.get());
    bound.bindBuffer(4, renderer.sceneBuffer_);
    return renderer;
}

Status GpuSphereRenderer::uploadMaterials(std::span<const MaterialInstance> materials) {
    // Tables are built first (in parallel, each into its own slot) to learn their sizes.
    std::vector<LobeTable> lobeTables(materials.size());
    parallelForChunks(int(materials.size()), [&](int i) {
        lobeTables[std::size_t(i)] = LobeTable::build(materials[std::size_t(i)], *tables_);
    });
    std::vector<GpuMaterial> gpuMaterials(std::max<std::size_t>(materials.size(), 1));
    uint32_t entryCount = 0;
    for (std::size_t i = 0; i < lobeTables.size(); ++i) {
        gpuMaterials[i] = {entryCount, uint32_t(lobeTables[i].texelNodes()),
                           uint32_t(lobeTables[i].cosineNodes()), 0};
        entryCount += uint32_t(lobeTables[i].data().size() / LobeTable::kFloatsPerEntry);
    }
    const VkDeviceSize materialBytes = gpuMaterials.size() * sizeof(GpuMaterial);
    const VkDeviceSize tableBytes =
        std::max<VkDeviceSize>(entryCount, 1) * LobeTable::kFloatsPerEntry * sizeof(float);
    for (auto [buffer, bytes] :
         {std::pair{&materialBuffer_, materialBytes}, std::pair{&lobeTableBuffer_, tableBytes}}) {
        if (buffer->size() >= bytes) continue;
        auto grown =
            Buffer::create(*device_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload);
        if (!grown) return grown.error();
        *buffer = std::move(grown).value();
    }
    std::memcpy(materialBuffer_.bytes().data(), gpuMaterials.data(), materialBytes);
    auto entries = lobeTableBuffer_.as<float>().begin();
    for (const LobeTable& table : lobeTables)
        entries = std::copy(table.data().begin(), table.data().end(), entries);
    return Ok{};
}

Status GpuSphereRenderer::record(VkCommandBuffer commands,
                                 std::span<const MaterialInstance> materials,
                                 const SceneSettings& scene, int size, const Buffer& renders) {
    if (auto uploaded = uploadMaterials(materials); !uploaded) return uploaded.error();
    const GpuScene gpuScene = toGpu(scene, size, textured_);
    std::memcpy(sceneBuffer_.bytes().data(), &gpuScene, sizeof(gpuScene));

    kernel_.bindBuffer(0, materialBuffer_);
    kernel_.bindBuffer(1, renders);
    kernel_.bindBuffer(5, lobeTableBuffer_);
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
