#pragma once
// The scene renderer's fixed-function visibility pass, the fast one on a GPU: one instanced
// draw of the mesh over the instances in view, depth-tested into a 4x multisampled depth
// buffer, each sample keeping the identity of its nearest triangle (SceneSurfaces.frag) in a
// 4x multisampled R32_UINT attachment. The identities are the compute pass's
// (shaders/SceneVisibility.glsl), so one shading pass reads either: it samples both
// attachments, which end each frame in SHADER_READ_ONLY_OPTIMAL, visible to fragment shaders.
#include <cstdint>
#include <span>

#include <glm/mat4x4.hpp>

#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/DescriptorSet.h"
#include "gpu/GpuImage.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

class SceneRasterVisibility {
public:
    // One instance of the draw; std430 layout of SceneSurfaces.vert's DrawnInstance.
    struct DrawnInstance {
        glm::mat4 clipFromObject;
        uint32_t firstSurface = 0;  // the identity of its first triangle
        uint32_t padding[3] = {};
    };

    // Whether the device can run the pass (gl_PrimitiveID in fragment shaders, 4x multisampled
    // integer and depth attachments it can also sample); an Error saying what it lacks.
    static Status supportedOn(const Device& device);

    // `vertices` holds the mesh's MeshVertex array (with vertex-buffer usage) and must outlive
    // the pass; `indices` are its triangles, three per triangle, in the order gl_PrimitiveID
    // counts them, filled into the pass's index buffer the way `indexFill` says
    // (Buffer::createFilled).
    static Result<SceneRasterVisibility> create(const Device& device, CommandRunner& runner,
                                                VkBuffer vertices,
                                                std::span<const uint32_t> indices,
                                                FillPath indexFill);

    // (Re)creates the attachments when the size changes, so no submission may be using them.
    Status prepareTarget(int width, int height);
    // Records the pass over `drawn`, after prepareTarget.
    Status record(VkCommandBuffer commands, std::span<const DrawnInstance> drawn);

    VkImageView surfaces() const { return surfaces_.view(); }
    VkImageView depths() const { return depths_.view(); }

private:
    const Device* device_ = nullptr;
    VkBuffer vertices_ = VK_NULL_HANDLE;
    Buffer indices_;
    uint32_t indexCount_ = 0;
    Buffer drawn_;  // DrawnInstance per instance in view, grown as needed
    DescriptorSet descriptors_;
    UniqueRenderPass renderPass_;
    UniquePipelineLayout pipelineLayout_;
    UniquePipeline pipeline_;
    int width_ = 0;
    int height_ = 0;
    GpuImage surfaces_;
    GpuImage depths_;
    UniqueFramebuffer framebuffer_;
};

}  // namespace matevo::gpu
