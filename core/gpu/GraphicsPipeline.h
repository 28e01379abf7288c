#pragma once
// One way to build a graphics pipeline: a vertex and a fragment shader, triangle lists, a
// dynamic viewport and scissor, and the few choices our raster passes differ in (the scene's
// depth-tested meshes and its full-screen shading pass, the editor's alpha-blended image
// quads).
#include <cstdint>
#include <span>
#include <string>

#include "common/Result.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

struct GraphicsPipelineSpec {
    std::span<const uint32_t> vertexSpirv;
    std::span<const uint32_t> fragmentSpirv;
    const VkSpecializationInfo* fragmentSpecialization = nullptr;  // kept alive by the caller
    VkVertexInputBindingDescription vertexBinding{};               // unused without attributes
    std::span<const VkVertexInputAttributeDescription> vertexAttributes;  // none: gl_VertexIndex
    // Counter-clockwise triangles face forward (core/mesh/Mesh.h; ImGui does not care).
    VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool depthTested = false;   // test LESS and write
    bool alphaBlended = false;  // straight-alpha "over", as ImGui blends
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkRenderPass renderPass = VK_NULL_HANDLE;
    uint32_t subpass = 0;
    std::string name;  // for the error message: "creating the <name> pipeline"
};

Result<UniquePipeline> createGraphicsPipeline(VkDevice device, const GraphicsPipelineSpec& spec);

}  // namespace matevo::gpu
