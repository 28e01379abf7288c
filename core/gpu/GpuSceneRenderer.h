#pragma once
// The scene view's renderer (shaders/SceneRaster.vert, .frag): one mesh drawn with one
// instanced draw, every instance with its own transform and material, forward shaded with
// 4x MSAA and a depth buffer into an RGBA16F image. Materials reach the GPU as the sphere
// compute shader's lobe tables (GpuMaterialTables) and are shaded by the same GLSL, so the
// two paths draw one BSDF.
//
// Forward, not deferred: one material lookup and one lighting pass per fragment, no G-buffer
// to write and read back at 4 samples per pixel (a deferred G-buffer with MSAA would multiply
// the memory traffic that bounds lavapipe), and a single light plus the environment gives a
// deferred pass nothing to amortise. docs/scene-view.md has the figures.
//
// Levels of detail (core/mesh/MeshSimplification.h): each instance is drawn from the finest
// level that gives its triangles a few pixels each on screen, one instanced draw per level,
// nearer instances first within a level so that the depth test rejects what they hide.
#include <span>
#include <vector>

#include "common/Image.h"
#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/CommandRunner.h"
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

class GpuSceneRenderer {
public:
    static constexpr VkSampleCountFlagBits kSamples = VK_SAMPLE_COUNT_4_BIT;
    static constexpr VkFormat kColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

    // `tables` must outlive the renderer (the process-wide defaultFgdTables() does).
    static Result<GpuSceneRenderer> create(const Device& device, CommandRunner& runner,
                                           const FgdTables& tables, const SceneTextures& textures,
                                           const Mesh& mesh);

    // Builds and uploads the materials' lobe tables; instances name them by index. Not while a
    // submission that draws them is in flight.
    Status setMaterials(std::span<const MaterialInstance> materials);

    // Records the frame: clears, draws every instance and resolves into resolvedImage(), which
    // ends in TRANSFER_SRC_OPTIMAL. (Re)creates the attachments when the size changes, so no
    // submission may be using them.
    Status record(VkCommandBuffer commands, const SceneFrame& frame, const SceneSettings& scene);

    // One submission: renders the frame and reads it back; linear RGB with straight alpha
    // (coverage of the multisamples), the background transparent.
    Result<Image> render(CommandRunner& runner, const SceneFrame& frame,
                         const SceneSettings& scene);

    const GpuImage& resolvedImage() const { return resolved_; }

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
    std::vector<DetailLevel> levels_;  // finest first, in vertices_ and indices_
    std::vector<uint32_t> levelInstances_;  // instances per level, consecutive in instances_
    Buffer frameBuffer_;  // the shaders' Frame block
    Buffer instances_;
    DescriptorSet descriptors_;
    UniqueRenderPass renderPass_;
    UniquePipelineLayout pipelineLayout_;
    UniquePipeline pipeline_;
    // Size-dependent: recreated by prepareTarget.
    int width_ = 0;
    int height_ = 0;
    GpuImage color_;
    GpuImage depth_;
    GpuImage resolved_;
    UniqueFramebuffer framebuffer_;
};

}  // namespace matevo::gpu
