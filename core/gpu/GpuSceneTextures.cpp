#include "gpu/GpuSceneTextures.h"

#include <vector>

#include "gpu/VulkanObjects.h"

namespace matevo::gpu {
namespace {

constexpr VkFormat kTextureFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

Status requireLinearSampling(const Device& device) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device.physicalDevice(), kTextureFormat, &properties);
    const VkFormatFeatureFlags needed =
        VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
    if ((properties.optimalTilingFeatures & needed) != needed)
        return environmentError("Vulkan: " + device.name() +
                                " cannot filter R32G32B32A32_SFLOAT textures linearly");
    return Ok{};
}

// An RGBA float texture from an image; the 1x1 `fill` texel for an empty image.
Result<GpuImage> uploadTexture(const Device& device, CommandRunner& runner, const Image& image,
                               float fill) {
    Image placeholder(1, 1);
    placeholder.rgba = {fill, fill, fill, 1.0f};
    const Image& source = image.width > 0 ? image : placeholder;
    GpuImageSpec spec;
    spec.format = kTextureFormat;
    spec.extent = {uint32_t(source.width), uint32_t(source.height), 1};
    return GpuImage::createFilled(device, runner, spec, std::as_bytes(std::span(source.rgba)));
}

// The levels stacked along z (one slice per roughness level, as PrefilteredEnvironment keeps
// them); a 1x1x1 black texture when there is no environment.
Result<GpuImage> uploadEnvironment(const Device& device, CommandRunner& runner,
                                   const PrefilteredEnvironment& environment) {
    GpuImageSpec spec;
    spec.type = VK_IMAGE_TYPE_3D;
    spec.format = kTextureFormat;
    std::vector<float> texels = {0.0f, 0.0f, 0.0f, 1.0f};
    if (!environment.empty()) {
        const Image& first = environment.levels.front();
        spec.extent = {uint32_t(first.width), uint32_t(first.height),
                       uint32_t(environment.levels.size())};
        texels.clear();
        for (const Image& level : environment.levels)
            texels.insert(texels.end(), level.rgba.begin(), level.rgba.end());
    }
    return GpuImage::createFilled(device, runner, spec, std::as_bytes(std::span(texels)));
}

}  // namespace

Result<GpuSceneTextures> GpuSceneTextures::create(const Device& device, CommandRunner& runner,
                                                  const SceneTextures& textures) {
    if (auto ok = requireLinearSampling(device); !ok) return ok.error();
    GpuSceneTextures uploaded;
    uploaded.textured_ = textures.roughness.width > 0 || textures.baseColor.width > 0;
    uploaded.environmentLevels_ = int(textures.environment.levels.size());
    auto roughness = uploadTexture(device, runner, textures.roughness, 1.0f);
    if (!roughness) return roughness.error();
    auto baseColor = uploadTexture(device, runner, textures.baseColor, 1.0f);
    if (!baseColor) return baseColor.error();
    auto environment = uploadEnvironment(device, runner, textures.environment);
    if (!environment) return environment.error();
    // Bilinear, wrapping in u and clamping in v, as sphereUv addresses them.
    auto sampler = createSampler(device.handle(), VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT);
    if (!sampler) return sampler.error();
    uploaded.roughness_ = std::move(roughness).value();
    uploaded.baseColor_ = std::move(baseColor).value();
    uploaded.environment_ = std::move(environment).value();
    uploaded.sampler_ = std::move(sampler).value();
    return uploaded;
}

void GpuSceneTextures::bind(const DescriptorSet& set, uint32_t roughnessBinding,
                            uint32_t baseColorBinding, uint32_t environmentBinding) const {
    set.bindSampledImage(roughnessBinding, roughness_.view(), sampler_.get());
    set.bindSampledImage(baseColorBinding, baseColor_.view(), sampler_.get());
    bindEnvironment(set, environmentBinding);
}

void GpuSceneTextures::bindEnvironment(const DescriptorSet& set,
                                       uint32_t environmentBinding) const {
    set.bindSampledImage(environmentBinding, environment_.view(), sampler_.get());
}

}  // namespace matevo::gpu
