#pragma once
// The renderer `matevo experiment` injects into the core experiment: the preset's material
// (family, kappa, textures, scene) bound, genomes in, sphere images out.
#include <optional>
#include <string_view>

#include "PresetOption.h"
#include "experiment/Experiment.h"

namespace matevo::cli {

enum class RenderBackend { Cpu };

std::optional<RenderBackend> parseRenderBackend(std::string_view text);

// Loads the preset's textures (a bad texture is a UsageError naming the preset and field).
// imageSize: pixels per side; the preset's scene size when absent.
RenderGenomes makeExperimentRenderer(const PresetChoice& choice, std::optional<int> imageSize,
                                     RenderBackend backend);

}  // namespace matevo::cli
