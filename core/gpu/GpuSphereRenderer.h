#pragma once
// The test sphere rendered on the GPU (shaders/SphereRender.comp): many materials per
// submission, the same scene, textures and FGD/TIR tables as the CPU reference
// renderSphereCpu. Tables and textures are uploaded once; each call uploads only the materials.
#include <span>
#include <vector>

#include "common/Image.h"
#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/CommandRunner.h"
#include "gpu/ComputeKernel.h"
#include "gpu/GpuImage.h"
#include "gpu/ImageBatch.h"
#include "material/FgdTables.h"
#include "material/MaterialInstance.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo::gpu {

class GpuSphereRenderer {
public:
    static Result<GpuSphereRenderer> create(const Device& device, CommandRunner& runner,
                                            const FgdTables& tables,
                                            const SceneTextures& textures);

    // Records the render of `materials` at size x size into `renders` (ImageBatch layout,
    // materials.size() images). Uploads the materials and scene into buffers it keeps, so the
    // caller must wait for the submission before recording again.
    Status record(VkCommandBuffer commands, std::span<const MaterialInstance> materials,
                  const SceneSettings& scene, int size, const Buffer& renders);

    // One submission: renders every material and reads the images back.
    Result<std::vector<Image>> render(CommandRunner& runner,
                                      std::span<const MaterialInstance> materials,
                                      const SceneSettings& scene, int size);

private:
    const Device* device_ = nullptr;
    TableGrid grid_;
    GpuImage fgd_;
    GpuImage tir_;
    GpuImage roughness_;
    GpuImage baseColor_;
    UniqueSampler tableSampler_;    // trilinear, clamped
    UniqueSampler textureSampler_;  // bilinear, wraps in u and clamps in v like sphereUv
    Buffer sceneBuffer_;
    Buffer materialBuffer_;
    ComputeKernel kernel_;
};

}  // namespace matevo::gpu
