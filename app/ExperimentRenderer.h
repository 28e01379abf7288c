#pragma once
// The renderer `matevo experiment` injects into the core experiment: the preset's material
// (family, kappa, textures, scene) bound, genomes in, sphere images out, on the chosen back end.
// One renderer serves every batch of a preset, so tables and textures are uploaded once.
#include <optional>

#include "PresetOption.h"
#include "RenderBackend.h"
#include "experiment/Experiment.h"

namespace matevo::cli {

// Loads the preset's textures (a bad texture is a UsageError naming the preset and field).
// imageSize: pixels per side; the preset's scene size when absent.
RenderGenomes makeExperimentRenderer(const PresetChoice& choice, std::optional<int> imageSize,
                                     const gpu::RendererRequest& rendererRequest);

}  // namespace matevo::cli
