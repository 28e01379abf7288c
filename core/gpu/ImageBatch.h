#pragma once
// Host-visible buffers holding a batch of same-sized images or ΔE00 or ꟻLIP maps, one after another
// in the layout of Image::rgba, and their conversion to and from the core types.
#include <cstdint>
#include <span>

#include "color/Flip.h"
#include "color/ImageDifference.h"
#include "common/Image.h"
#include "common/Result.h"
#include "gpu/Buffer.h"

namespace matevo::gpu {

struct ImageBatchShape {
    int width = 0;
    int height = 0;
    uint32_t count = 0;

    uint32_t pixelCount() const { return uint32_t(width) * uint32_t(height); }
};

// A buffer for `shape.count` RGBA float images (channels = 4) or float maps (channels = 1):
// a storage buffer, also usable as a uniform texel buffer (the ꟻLIP pass reads images so).
Result<Buffer> createBatchBuffer(const Device& device, const ImageBatchShape& shape, int channels,
                                 MemoryUse use);

// Records filling the batch's `shape.count` slots with `value` in every channel, ordered after
// earlier work on the buffer and before compute shaders of the same submission read or write
// it (a pass that writes only some pixels clears the rest this way).
void recordClear(VkCommandBuffer commands, const Buffer& batch, const ImageBatchShape& shape,
                 int channels, float value);

// Records ordering earlier passes and copies that read or write a batch before compute shaders
// of the same submission write it again (what recordClear orders, when the fill is skipped).
void recordRewrite(VkCommandBuffer commands);

// Copies image into slot `index` (sizes must match the shape).
void uploadImage(const Buffer& batch, const ImageBatchShape& shape, uint32_t index,
                 const Image& image);
Image downloadImage(const Buffer& batch, const ImageBatchShape& shape, uint32_t index);

// The error map the pass of `metric` wrote, with its statistics pooled as on the CPU. Covered
// pixels hold the error e ≥ 0; elsewhere the ΔE00 pass writes −1 (kept as 0) and the ꟻLIP pass
// −1 − e (kept as e), as ErrorMap says.
ErrorMap downloadErrorMap(const Buffer& batch, const ImageBatchShape& shape, uint32_t index,
                          ImageMetric metric);

}  // namespace matevo::gpu
