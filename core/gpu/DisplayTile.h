#pragma once
// What the editor's window samples: a render (linear RGBA float) and, for a candidate, its
// ΔE00 map against the target (one float per pixel, negative where not covered), as images on
// the window's device. A tile is written once on the GPU (GpuPopulationRenderer copies its
// buffers in, uploadToTiles copies host pictures in, or GpuSceneRenderer::recordDisplay writes
// the Scene window's picture), left in SHADER_READ_ONLY_OPTIMAL with
// a barrier that makes it visible to fragment shaders of later submissions, and never changed
// afterwards: readers on other threads need no lock, only a reference that keeps it alive.
#include <optional>
#include <span>

#include "color/ImageDifference.h"
#include "common/Image.h"
#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/CommandRunner.h"
#include "gpu/GpuImage.h"
#include "gpu/ImageBatch.h"

namespace matevo::gpu {

struct DisplayTile {
    int width = 0;
    int height = 0;
    GpuImage render;
    std::optional<GpuImage> deltaE;

    static Result<DisplayTile> create(const Device& device, int width, int height, bool withDeltaE);
};

// Records copies of image i of `renders` (and of `deltaE`, when given, into tiles that have
// a ΔE00 map) into tiles[i], after the compute writes that produced them.
void recordCopiesToTiles(VkCommandBuffer commands, const Buffer& renders, const Buffer* deltaE,
                         const ImageBatchShape& shape, std::span<const DisplayTile* const> tiles);

// Host pictures into tiles, one submission: renders[i] (and maps[i] when maps is not empty)
// into tiles[i]. Sizes must match the tiles'.
Status uploadToTiles(const Device& device, CommandRunner& runner,
                     std::span<const DisplayTile* const> tiles, std::span<const Image> renders,
                     std::span<const ErrorMap> maps);

}  // namespace matevo::gpu
