#pragma once
// The test sphere rendered on the GPU (shaders/SphereRender.comp): many materials per
// submission, the same scene and textures as the CPU reference renderSphereCpu, shading the
// same points (core/scene/SphereSamples.h, traced once per camera and size). Each material's
// LobeTable is built on the CPU (the same numbers the CPU renderer shades from, so the back ends
// agree) and uploaded with the materials; the shader interpolates it and evaluates the lobes.
#include <span>
#include <vector>

#include "common/Image.h"
#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/CommandRunner.h"
#include "gpu/ComputeKernel.h"
#include "gpu/GpuMaterialTables.h"
#include "gpu/GpuSceneTextures.h"
#include "gpu/GpuSphereSamples.h"
#include "gpu/ImageBatch.h"
#include "material/FgdTables.h"
#include "material/MaterialInstance.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo::gpu {

// What a render compares each candidate with as it shades it (the ΔE00 pass's output, fused
// into the render): buffers in ImageBatch layout of the render's shape.
struct TargetComparison {
    VkBufferView targetLab = VK_NULL_HANDLE;  // RGBA32F per pixel of one image: L*, a*, b*, alpha
    const Buffer* deltaE = nullptr;           // 1 float per pixel, -1 where not covered in both
};

class GpuSphereRenderer {
public:
    // `tables` must outlive the renderer (the process-wide defaultFgdTables() does).
    static Result<GpuSphereRenderer> create(const Device& device, CommandRunner& runner,
                                            const FgdTables& tables, const SceneTextures& textures);

    // Records the render of `materials` at size x size into `renders` (ImageBatch layout,
    // materials.size() images). Uploads the materials' lobe tables and the scene into buffers
    // it keeps, so the caller must wait for the submission before recording again.
    // With a comparison it also writes the ΔE00 maps against the target.
    // The shader writes covered pixels only; the background is filled first unless
    // `backgroundFilled` says that these buffers hold an earlier render of the same coverage
    // (GpuSphereSamples::Key) and nothing wrote their background since.
    Status record(VkCommandBuffer commands, std::span<const MaterialInstance> materials,
                  const SceneSettings& scene, int size, const Buffer& renders,
                  const TargetComparison* comparison = nullptr, bool backgroundFilled = false);

    // One submission: renders every material and reads the images back.
    Result<std::vector<Image>> render(CommandRunner& runner,
                                      std::span<const MaterialInstance> materials,
                                      const SceneSettings& scene, int size);

private:
    const Device* device_ = nullptr;
    const FgdTables* tables_ = nullptr;
    GpuSceneTextures textures_;
    Buffer sceneBuffer_;
    GpuMaterialTables materials_;
    GpuSphereSamples samples_;
    // [compared with a target][silhouette]: pixels shaded at one point, or the silhouette's
    // pixels of several points; rendered only, or also compared with a target.
    ComputeKernel kernels_[2][2];
};

}  // namespace matevo::gpu
