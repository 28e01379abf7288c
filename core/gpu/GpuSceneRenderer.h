#pragma once
// The scene view's renderer: one mesh drawn with one instanced draw, every instance with its
// own transform and material, deferred-shaded into an RGBA16F image. Materials reach the GPU
// as the sphere compute shader's lobe tables (GpuMaterialTables) and are shaded by the same
// GLSL, so the two paths draw one BSDF.
//
// Deferred, one sample per pixel, chosen by measurement on lavapipe (docs/scene-view.md): a
// surface pass (shaders/SceneSurface.frag) stores each pixel's nearest normal, texture
// coordinates and material, then a full-screen pass (shaders/SceneShade.frag) shades each
// covered pixel once. lavapipe shades fragments in 4x4-pixel blocks, so forward shading of a
// mesh whose triangles are a few pixels each shaded most pixels several times; 4x MSAA cost
// 2.4x more again.
//
// Levels of detail (core/mesh/MeshSimplification.h): each instance is drawn from the finest
// level that gives its triangles a few pixels each on screen, one instanced draw per level,
// nearer instances first within a level so that the depth test rejects what they hide.
#include <optional>
#include <span>
#include <vector>

#include "common/Image.h"
#include "color/ToneMap.h"
#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/CommandRunner.h"
#include "gpu/ComputeKernel.h"
#include "gpu/DescriptorSet.h"
#include "gpu/GpuImage.h"
#include "gpu/GpuMaterialTables.h"
#include "gpu/GpuSceneTextures.h"
#include "material/FgdTables.h"
#include "material/MaterialInstance.h"
#include "mesh/Mesh.h"
#include "scene/SceneLayout.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo::gpu {

struct SceneFrame {
    int width = 0;
    int height = 0;
    SceneCamera camera;
    std::span<const SceneInstance> instances;
};

// How the scene becomes a displayable picture (SceneDisplay.comp).
struct SceneDisplay {
    double exposureStops = 0.0;
    ToneMap toneMap = ToneMap::Aces;
};

class GpuSceneRenderer {
public:
    static constexpr VkFormat kColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

    // `tables` must outlive the renderer (the process-wide defaultFgdTables() does).
    static Result<GpuSceneRenderer> create(const Device& device, CommandRunner& runner,
                                           const FgdTables& tables, const SceneTextures& textures,
                                           const Mesh& mesh);

    // Builds and uploads the materials' lobe tables; instances name them by index. Not while a
    // submission that draws them is in flight.
    Status setMaterials(std::span<const MaterialInstance> materials);

    // Records the frame: clears, draws every instance and shades it into radianceImage(),
    // which ends in GENERAL, visible to transfers and compute shaders. (Re)creates the attachments when the size changes, so no
    // submission may be using them.
    Status record(VkCommandBuffer commands, const SceneFrame& frame, const SceneSettings& scene);

    // Records, after record(): the radiance over the environment's slightly blurred backdrop
    // (opaque; without an environment the background stays transparent), exposed and tone
    // mapped into `target` (RGBA32F, storage and sampled usage, the frame's size), which ends
    // in SHADER_READ_ONLY_OPTIMAL, visible to later fragment shaders and transfers. The GPU
    // twin of compositeOverEnvironment and applyExposureAndToneMap: the editor's Scene window
    // samples `target` with no copy through the host.
    Status recordDisplay(VkCommandBuffer commands, const GpuImage& target,
                         const SceneDisplay& display);

    // One submission: renders the frame and reads it back. Without `display`: linear RGB,
    // alpha 1 where an instance is drawn, the background transparent. With it: the
    // displayable picture recordDisplay makes.
    Result<Image> render(CommandRunner& runner, const SceneFrame& frame,
                         const SceneSettings& scene,
                         std::optional<SceneDisplay> display = std::nullopt);

    const GpuImage& radianceImage() const { return radiance_; }

private:
    Status prepareTarget(int width, int height);
    // Uploads the instances grouped by level of detail; fills levelInstances_.
    Status prepareInstances(const SceneFrame& frame);

    const Device* device_ = nullptr;
    const FgdTables* tables_ = nullptr;
    GpuSceneTextures textures_;
    GpuMaterialTables materials_;
    uint32_t materialCount_ = 0;
    Buffer vertices_;
    Buffer indices_;
    struct DetailLevel {
        uint32_t firstIndex = 0;
        uint32_t indexCount = 0;
        int32_t vertexOffset = 0;
    };
    std::vector<DetailLevel> levels_;       // finest first, in vertices_ and indices_
    std::vector<uint32_t> levelInstances_;  // instances per level, consecutive in instances_
    Buffer frameBuffer_;                    // the shaders' Frame block
    Buffer instances_;
    DescriptorSet descriptors_;
    UniqueRenderPass renderPass_;
    UniquePipelineLayout pipelineLayout_;
    UniquePipeline surfacePipeline_;
    UniquePipeline shadingPipeline_;
    ComputeKernel displayKernel_;
    // Size-dependent: recreated by prepareTarget.
    int width_ = 0;
    int height_ = 0;
    GpuImage surfaces_;
    GpuImage depth_;
    GpuImage radiance_;
    UniqueFramebuffer framebuffer_;
};

}  // namespace matevo::gpu
