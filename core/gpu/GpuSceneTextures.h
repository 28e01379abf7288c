#pragma once
// The scene's textures on the GPU, shared by the sphere compute shader and the raster scene
// renderer: roughness and base colour (2D, bilinear, wrapping in u and clamping in v like
// sphereUv) and the prefiltered environment (3D: lat-long by roughness level, the same
// addressing). Absent ones are 1x1 placeholders (white textures, black environment).
#include "common/Result.h"
#include "gpu/CommandRunner.h"
#include "gpu/DescriptorSet.h"
#include "gpu/Device.h"
#include "gpu/GpuImage.h"
#include "scene/SceneTextures.h"

namespace matevo::gpu {

class GpuSceneTextures {
public:
    static Result<GpuSceneTextures> create(const Device& device, CommandRunner& runner,
                                           const SceneTextures& textures);

    // A texture is present: shaders need the UV.
    bool textured() const { return textured_; }
    // Roughness levels of the environment; 0 when there is none.
    int environmentLevels() const { return environmentLevels_; }

    void bind(const DescriptorSet& set, uint32_t roughnessBinding, uint32_t baseColorBinding,
              uint32_t environmentBinding) const;
    void bindEnvironment(const DescriptorSet& set, uint32_t environmentBinding) const;

private:
    bool textured_ = false;
    int environmentLevels_ = 0;
    GpuImage roughness_;
    GpuImage baseColor_;
    GpuImage environment_;
    UniqueSampler sampler_;
};

}  // namespace matevo::gpu
