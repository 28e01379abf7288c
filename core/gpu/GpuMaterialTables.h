#pragma once
// Materials on the GPU as the shaders read them (shaders/LobeTable.glsl): one record per
// material pointing into one buffer holding every material's LobeTable, built on the CPU (the
// numbers the CPU renderer shades from, so the back ends agree). Used by the sphere compute
// shader and the raster scene renderer.
#include <span>

#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/Device.h"
#include "material/FgdTables.h"
#include "material/MaterialInstance.h"

namespace matevo::gpu {

class GpuMaterialTables {
public:
    // Builds the tables (in parallel) and writes them, growing the buffers when needed; the
    // caller must not upload while a submission reads them.
    Status upload(const Device& device, const FgdTables& tables,
                  std::span<const MaterialInstance> materials);

    // One RGBA32UI texel per material (a uniform texel buffer).
    VkBufferView materials() const { return materials_.view.get(); }
    // Every material's lobe-table entries as RGBA32F texels (a uniform texel buffer).
    VkBufferView lobeEntries() const { return lobeEntries_.view.get(); }

private:
    TexelBuffer materials_;
    TexelBuffer lobeEntries_;
};

}  // namespace matevo::gpu
