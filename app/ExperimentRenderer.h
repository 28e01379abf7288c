#pragma once
// The renderer `matevo experiment` injects into the core experiment: the preset's material
// (family, kappa, textures, scene) bound, genomes in, sphere images out. On the GPU, one Vulkan
// session serves every batch of the experiment; when no Vulkan device is usable it says so once
// on stderr and renders on the CPU reference.
#include <functional>
#include <optional>
#include <string>

#include "PresetOption.h"
#include "RenderBackend.h"
#include "experiment/Experiment.h"

namespace matevo::cli {

// Genomes of the preset's material rendered at any size, one session for every call.
using RenderGenomesAtSize =
    std::function<Result<std::vector<Image>>(std::span<const Genome> genomes, int size)>;

// Loads the preset's textures (a bad texture is a UsageError naming the preset and field).
// `command` prefixes the CPU fallback notice.
RenderGenomesAtSize makeGenomeRenderer(const PresetChoice& choice, RenderBackend backend,
                                       const std::string& command);

// The same at one size. imageSize: pixels per side; the preset's scene size when absent.
RenderGenomes makeExperimentRenderer(const PresetChoice& choice, std::optional<int> imageSize,
                                     RenderBackend backend);

}  // namespace matevo::cli
