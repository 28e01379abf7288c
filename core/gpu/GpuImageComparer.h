#pragma once
// ΔE00 or ꟻLIP maps on the GPU for images that already exist on the host (e.g. CPU renders):
// upload, one submission of the compute pass, read back. The GPU renderer feeds the same passes
// straight from its own buffers instead.
#include <functional>
#include <span>
#include <vector>

#include "color/Flip.h"
#include "color/ImageDifference.h"
#include "common/Image.h"
#include "common/Result.h"
#include "gpu/CommandRunner.h"
#include "gpu/DeltaE00Pass.h"
#include "gpu/FlipPass.h"
#include "gpu/ImageBatch.h"

namespace matevo::gpu {

class GpuImageComparer {
public:
    static Result<GpuImageComparer> create(const Device& device);

    // One map per candidate; every candidate must have the reference's size.
    Result<std::vector<ErrorMap>> compare(const Image& reference,
                                          std::span<const Image> candidates);
    Result<std::vector<ErrorMap>> compareFlip(const Image& reference,
                                              std::span<const Image> candidates,
                                              const FlipSettings& settings = {});

private:
    // The images in upload buffers, and a read-back buffer for one map per candidate: kept from
    // call to call, made anew only for a larger batch. (Fresh buffers at every call cost a page
    // fault per 4 KiB touched, or not, as the C library's allocator happened to hand out memory: at
    // 256² that was up to four times the ΔE00 pass's time.)
    struct Buffers {
        Buffer reference, candidates, maps;
    };
    // Copies the images into buffers_ (made or grown first when needed).
    Result<ImageBatchShape> upload(const Image& reference, std::span<const Image> candidates);
    // Uploads, records the metric's pass with `record`, submits and reads the maps back.
    using RecordPass = std::function<Status(VkCommandBuffer, const ImageBatchShape&)>;
    Result<std::vector<ErrorMap>> measure(const Image& reference, std::span<const Image> candidates,
                                          ImageMetric metric, const RecordPass& record);

    const Device* device_ = nullptr;
    DeltaE00Pass deltaEPass_;
    FlipPass flipPass_;
    CommandRunner runner_;
    Buffers buffers_;
};

}  // namespace matevo::gpu
