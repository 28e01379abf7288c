#include "gpu/GpuMaterialTables.h"

#include <algorithm>
#include <cstring>
#include <tuple>
#include <vector>

#include "common/ParallelFor.h"
#include "material/LobeTable.h"

namespace matevo::gpu {
namespace {

// shaders/LobeTable.glsl's Material, one RGBA32UI texel.
struct GpuMaterial {
    uint32_t firstEntry;  // of its lobe table, in entries
    uint32_t texelNodes;  // TexelAxis::nodes | TexelAxis::kneeNode << 16
    uint32_t cosineNodes;
    float texelKnee;  // TexelAxis::knee, read as uintBitsToFloat
};
static_assert(sizeof(GpuMaterial) == 16, "one RGBA32UI texel");

}  // namespace

Status GpuMaterialTables::upload(const Device& device, const FgdTables& tables,
                                 std::span<const MaterialInstance> materials) {
    // Tables are built first (in parallel, each into its own slot) to learn their sizes.
    std::vector<LobeTable> lobeTables(materials.size());
    parallelForChunks(int(materials.size()), [&](int i) {
        lobeTables[std::size_t(i)] = LobeTable::build(materials[std::size_t(i)], tables);
    });
    std::vector<GpuMaterial> gpuMaterials(std::max<std::size_t>(materials.size(), 1));
    uint32_t entryCount = 0;
    for (std::size_t i = 0; i < lobeTables.size(); ++i) {
        const TexelAxis& texelAxis = lobeTables[i].texelAxis();
        gpuMaterials[i] = {entryCount,
                           uint32_t(texelAxis.nodes) | uint32_t(texelAxis.kneeNode) << 16,
                           uint32_t(lobeTables[i].cosineNodes()), float(texelAxis.knee)};
        entryCount += uint32_t(lobeTables[i].data().size() / LobeTable::kFloatsPerEntry);
    }
    const VkDeviceSize materialBytes = gpuMaterials.size() * sizeof(GpuMaterial);
    const VkDeviceSize tableBytes =
        std::max<VkDeviceSize>(entryCount, 1) * LobeTable::kFloatsPerEntry * sizeof(float);
    for (auto [buffer, bytes, format] :
         {std::tuple{&materials_, materialBytes, VK_FORMAT_R32G32B32A32_UINT},
          std::tuple{&lobeEntries_, tableBytes, VK_FORMAT_R32G32B32A32_SFLOAT}}) {
        if (buffer->buffer.size() >= bytes) continue;
        auto grown = createTexelBuffer(device, bytes, format);
        if (!grown) return grown.error();
        *buffer = std::move(grown).value();
    }
    std::memcpy(materials_.buffer.bytes().data(), gpuMaterials.data(), materialBytes);
    auto entries = lobeEntries_.buffer.as<float>().begin();
    for (const LobeTable& table : lobeTables)
        entries = std::copy(table.data().begin(), table.data().end(), entries);
    return Ok{};
}

}  // namespace matevo::gpu
