#pragma once
// The scene view's renderer: every instance of one mesh with its own transform and material,
// shaded into an RGBA16F image. Materials reach the GPU as the sphere compute shader's lobe
// tables (GpuMaterialTables) and are shaded by the same GLSL, so the two paths draw one BSDF.
//
// Two passes. A visibility pass finds, for each of a pixel's 4 samples (the standard 4x
// multisample positions), the depth and the triangle of the nearest surface. It comes in two
// kinds that give the same picture (SceneVisibilityPass; docs/scene-view.md says which is
// faster where, by measurement): a rasteriser in a compute shader
// (shaders/SceneRasterize.comp, one 64-bit atomicMin word per sample), chosen on CPU devices
// such as lavapipe, whose fixed-function front end runs on one thread; and the fixed-function
// rasteriser (SceneRasterVisibility: one instanced draw, depth buffer, 4x MSAA), chosen on
// GPUs. The shading pass (shaders/SceneShade.frag, one source for both) then shades
// each surface among a pixel's samples once, interpolating the triangle's normal and texture
// coordinates where the pixel's ray meets it, and weights it by its samples: silhouettes are
// blended, and alpha is the share of the samples covered. Every instance is drawn with
// the whole mesh; instances outside the view are dropped on the CPU first, and, for the
// compute pass, clusters of triangles that all face away from the camera
// (core/mesh/MeshClusters.h; the fixed-function pass culls back faces itself).
#include <optional>
#include <span>
#include <vector>

#include "color/ToneMap.h"
#include "common/Image.h"
#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/CommandRunner.h"
#include "gpu/ComputeKernel.h"
#include "gpu/DescriptorSet.h"
#include "gpu/GpuImage.h"
#include "gpu/GpuMaterialTables.h"
#include "gpu/GpuSceneTextures.h"
#include "gpu/SceneRasterVisibility.h"
#include "gpu/SceneVisibilityPass.h"
#include "material/FgdTables.h"
#include "material/MaterialInstance.h"
#include "mesh/Mesh.h"
#include "mesh/MeshClusters.h"
#include "scene/SceneLayout.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo::gpu {

struct SceneFrame {
    int width = 0;
    int height = 0;
    SceneCamera camera;
    std::span<const SceneInstance> instances;
    // Drop the clusters that face away from the camera before the compute visibility pass. It
    // changes no pixel (the pass drops back faces itself); off only to show that (tests,
    // bench). The raster pass always draws the whole mesh.
    bool cullClusters = true;
};

// How the scene becomes a displayable picture (SceneDisplay.comp).
struct SceneDisplay {
    double exposureStops = 0.0;
    ToneMap toneMap = ToneMap::Aces;
};

class GpuSceneRenderer {
public:
    static constexpr VkFormat kColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

    // `tables` must outlive the renderer (the process-wide defaultFgdTables() does). Auto
    // picks the visibility pass by the device's type; an Error when the device cannot run the
    // one asked for. The mesh's buffers are filled once, in device-local memory, the way
    // `meshFill` says (Buffer::createFilled; Staged only to test that path on lavapipe).
    static Result<GpuSceneRenderer> create(
        const Device& device, CommandRunner& runner, const FgdTables& tables,
        const SceneTextures& textures, const Mesh& mesh,
        SceneVisibilityPass visibility = SceneVisibilityPass::Auto,
        FillPath meshFill = FillPath::Auto);

    // Builds and uploads the materials' lobe tables; instances name them by index. Not while a
    // submission that draws them is in flight.
    Status setMaterials(std::span<const MaterialInstance> materials);

    // Records the frame: clears, draws every instance and shades it into radianceImage(),
    // which ends in GENERAL, visible to transfers and compute shaders. (Re)creates the attachments
    // when the size changes, so no submission may be using them.
    Status record(VkCommandBuffer commands, const SceneFrame& frame, const SceneSettings& scene);

    // Records, after record(): the radiance over the environment's slightly blurred backdrop
    // (opaque; without an environment the background stays transparent), exposed and tone
    // mapped into `target` (RGBA32F, storage and sampled usage, the frame's size), which ends
    // in SHADER_READ_ONLY_OPTIMAL, visible to later fragment shaders and transfers. The GPU
    // twin of compositeOverEnvironment and applyExposureAndToneMap: the editor's Scene window
    // samples `target` with no copy through the host.
    Status recordDisplay(VkCommandBuffer commands, const GpuImage& target,
                         const SceneDisplay& display);

    // One submission: renders the frame and reads it back. Without `display`: linear RGB (not
    // premultiplied), alpha the share of a pixel's samples an instance covers, the background
    // transparent. With it: the
    // displayable picture recordDisplay makes.
    Result<Image> render(CommandRunner& runner, const SceneFrame& frame, const SceneSettings& scene,
                         std::optional<SceneDisplay> display = std::nullopt);

    const GpuImage& radianceImage() const { return radiance_; }
    // Raster or Compute: the visibility pass this renderer runs.
    SceneVisibilityPass visibilityPass() const { return visibilityPass_; }
    // The last recorded frame's triangles sent to the visibility pass, after culling.
    uint64_t trianglesSubmitted() const { return trianglesSubmitted_; }

private:
    Status prepareTarget(int width, int height);
    // Records the visibility pass over instanceWork_, one kind or the other.
    Status recordComputeVisibility(VkCommandBuffer commands, const SceneFrame& frame);
    Status recordRasterVisibility(VkCommandBuffer commands);
    // Uploads the instances and the clusters in view; fills instanceWork_.
    Status prepareInstances(const SceneFrame& frame);
    // A host-visible buffer both passes read as texels of one format.
    struct TexelBuffer {
        Buffer buffer;
        UniqueBufferView view;
    };
    // Copies `bytes` into `target`, grown (and rebound in both passes' descriptor sets) when
    // too small.
    Status upload(TexelBuffer& target, std::span<const std::byte> bytes, VkFormat format,
                  uint32_t shadingBinding, std::optional<uint32_t> rasterizeBinding);

    const Device* device_ = nullptr;
    const FgdTables* tables_ = nullptr;
    SceneVisibilityPass visibilityPass_ = SceneVisibilityPass::Compute;
    GpuSceneTextures textures_;
    GpuMaterialTables materials_;
    uint32_t materialCount_ = 0;
    // The mesh, its triangles in clusters (core/mesh/MeshClusters.h), as texel buffers.
    Buffer vertices_;
    Buffer triangles_;
    UniqueBufferView verticesView_;
    UniqueBufferView trianglesView_;
    uint32_t triangleCount_ = 0;
    std::vector<MeshCluster> clusters_;
    Buffer frameBuffer_;           // the shaders' Frame block
    TexelBuffer instances_;        // every instance, in the frame's order
    TexelBuffer visibleClusters_;  // (instance, cluster) pairs of this frame
    // Per instance with clusters in view: one dispatch of the compute pass, one instance of
    // the raster pass's draw.
    struct InstanceWork {
        glm::mat4 clipFromObject;
        uint32_t firstEntry = 0;
        uint32_t entries = 0;
    };
    std::vector<InstanceWork> instanceWork_;
    uint64_t trianglesSubmitted_ = 0;
    ComputeKernel rasterizeKernel_;                          // the compute visibility pass
    std::optional<SceneRasterVisibility> rasterVisibility_;  // or the raster one
    DescriptorSet descriptors_;                              // the shading pass's
    UniqueRenderPass renderPass_;
    UniquePipelineLayout pipelineLayout_;
    UniquePipeline shadingPipeline_;
    ComputeKernel displayKernel_;
    // Size-dependent: recreated by prepareTarget.
    int width_ = 0;
    int height_ = 0;
    Buffer visibility_;  // the compute pass's 64-bit word per sample (SceneVisibility.glsl)
    UniqueBufferView visibilityView_;
    GpuImage radiance_;
    UniqueFramebuffer framebuffer_;
};

}  // namespace matevo::gpu
