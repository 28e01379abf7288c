#include "gpu/GpuSphereRenderer.h"

#include <cmath>
#include <cstring>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <shaders/kSphereRenderSpirv.h>

#include "gpu/VulkanError.h"
#include "material/LayerStack.h"

namespace matevo::gpu {
namespace {

constexpr uint32_t kWorkgroupSize = 64;  // local_size_x in the shader

// std430 mirrors of the shader's blocks.
struct GpuMaterial {
    float coatEta[4];
    float baseEta[4];
    float baseKappa[4];
    float sigmaS[4];
    float sigmaA[4];
};

struct GpuScene {
    float cameraPosition[4];
    float cameraForward[4];
    float cameraRight[4];
    float cameraUp[4];
    float toLight[4];
    float lightRadiance[4];
    float environmentRadiance[4];
    float tableAxes[4][4];
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

// The family's structure and the textures' neutral values come from makeLayerStack, so both
// back ends decide the same way which slots exist; the shader applies the texels per pixel.
GpuMaterial toGpu(const MaterialInstance& material) {
    const LayerStack stack = makeLayerStack(material);
    const double texturedLayer = material.family.texturedLayer == TexturedLayer::Top      ? 1.0
                                 : material.family.texturedLayer == TexturedLayer::Bottom ? 2.0
                                                                                          : 0.0;
    GpuMaterial gpu{};
    store(gpu.coatEta, stack.coat.eta, stack.coat.alpha);
    store(gpu.baseEta, stack.base.eta, stack.base.alpha);
    store(gpu.baseKappa, stack.base.kappa, texturedLayer);
    const MediumLayer medium = stack.medium.value_or(MediumLayer{});
    store(gpu.sigmaS, medium.sigmaS, stack.medium ? medium.depth : 0.0);
    store(gpu.sigmaA, medium.sigmaA, medium.g);
    return gpu;
}

GpuScene toGpu(const SceneSettings& scene, int size, const TableGrid& grid) {
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
    store(gpu.environmentRadiance, toVector(scene.environmentRadiance), 0.0);
    const TableAxis* axes[4] = {&grid.mu, &grid.alpha, &grid.eta, &grid.kappa};
    for (int i = 0; i < 4; ++i)
        store(gpu.tableAxes[i], {double(axes[i]->count), axes[i]->min, axes[i]->max}, 0.0);
    return gpu;
}

Status requireLinearSampling(const Device& device, VkFormat format, const char* what) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device.physicalDevice(), format, &properties);
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                        VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
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

Result<GpuImage> uploadTable(const Device& device, CommandRunner& runner,
                             const std::vector<float>& data, VkExtent3D extent) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device.physicalDevice(), &properties);
    const uint32_t largest = std::max({extent.width, extent.height, extent.depth});
    if (largest > properties.limits.maxImageDimension3D)
        return Error{"Vulkan: the FGD/TIR table needs 3D images of " + std::to_string(largest) +
                     " texels; " + device.name() + " allows " +
                     std::to_string(properties.limits.maxImageDimension3D)};
    GpuImageSpec spec;
    spec.type = VK_IMAGE_TYPE_3D;
    spec.format = VK_FORMAT_R32_SFLOAT;
    spec.extent = extent;
    return GpuImage::createFilled(device, runner, spec, std::as_bytes(std::span(data)));
}

}  // namespace

Result<GpuSphereRenderer> GpuSphereRenderer::create(const Device& device, CommandRunner& runner,
                                                    const FgdTables& tables,
                                                    const SceneTextures& textures) {
    if (auto ok = requireLinearSampling(device, VK_FORMAT_R32_SFLOAT, "R32_SFLOAT tables"); !ok)
        return ok.error();
    if (auto ok = requireLinearSampling(device, VK_FORMAT_R32G32B32A32_SFLOAT,
                                        "R32G32B32A32_SFLOAT textures");
        !ok)
        return ok.error();

    GpuSphereRenderer renderer;
    renderer.device_ = &device;
    renderer.grid_ = tables.grid();
    const TableGrid& grid = renderer.grid_;
    auto fgd = uploadTable(device, runner, tables.fgdData(),
                           {uint32_t(grid.kappa.count), uint32_t(grid.eta.count),
                            uint32_t(grid.alpha.count * grid.mu.count)});
    if (!fgd) return fgd.error();
    auto tir = uploadTable(device, runner, tables.tirData(),
                           {uint32_t(grid.eta.count), uint32_t(grid.alpha.count),
                            uint32_t(grid.mu.count)});
    if (!tir) return tir.error();
    auto roughness = uploadTexture(device, runner, textures.roughness);
    if (!roughness) return roughness.error();
    auto baseColor = uploadTexture(device, runner, textures.baseColor);
    if (!baseColor) return baseColor.error();
    auto tableSampler = createSampler(device, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                      VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
    if (!tableSampler) return tableSampler.error();
    auto textureSampler = createSampler(device, VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
    if (!textureSampler) return textureSampler.error();
    auto sceneBuffer = Buffer::create(device, sizeof(GpuScene),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload);
    if (!sceneBuffer) return sceneBuffer.error();

    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    auto kernel = ComputeKernel::create(
        device, kSphereRenderSpirv,
        {storage, storage, sampled, sampled, sampled, sampled, storage}, 0);
    if (!kernel) return kernel.error();

    renderer.fgd_ = std::move(fgd).value();
    renderer.tir_ = std::move(tir).value();
    renderer.roughness_ = std::move(roughness).value();
    renderer.baseColor_ = std::move(baseColor).value();
    renderer.tableSampler_ = std::move(tableSampler).value();
    renderer.textureSampler_ = std::move(textureSampler).value();
    renderer.sceneBuffer_ = std::move(sceneBuffer).value();
    renderer.kernel_ = std::move(kernel).value();
    const ComputeKernel& bound = renderer.kernel_;
    bound.bindSampledImage(2, renderer.fgd_.view(), renderer.tableSampler_.get());
    bound.bindSampledImage(3, renderer.tir_.view(), renderer.tableSampler_.get());
    bound.bindSampledImage(4, renderer.roughness_.view(), renderer.textureSampler_.get());
    bound.bindSampledImage(5, renderer.baseColor_.view(), renderer.textureSampler_.get());
    bound.bindBuffer(6, renderer.sceneBuffer_);
    return renderer;
}

Status GpuSphereRenderer::record(VkCommandBuffer commands,
                                 std::span<const MaterialInstance> materials,
                                 const SceneSettings& scene, int size, const Buffer& renders) {
    const VkDeviceSize materialBytes = std::max<std::size_t>(materials.size(), 1) *
                                       sizeof(GpuMaterial);
    if (materialBuffer_.size() < materialBytes) {
        auto grown = Buffer::create(*device_, materialBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                    MemoryUse::Upload);
        if (!grown) return grown.error();
        materialBuffer_ = std::move(grown).value();
    }
    auto gpuMaterials = materialBuffer_.as<GpuMaterial>();
    for (std::size_t i = 0; i < materials.size(); ++i) gpuMaterials[i] = toGpu(materials[i]);
    const GpuScene gpuScene = toGpu(scene, size, grid_);
    std::memcpy(sceneBuffer_.bytes().data(), &gpuScene, sizeof(gpuScene));

    kernel_.bindBuffer(0, materialBuffer_);
    kernel_.bindBuffer(1, renders);
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
