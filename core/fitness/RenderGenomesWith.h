#pragma once
// The seam RenderGenomes (evolve/RenderGenomes.h) served by the render interface.
#include <array>
#include <memory>

#include "evolve/RenderGenomes.h"
#include "genome/MaterialFamily.h"
#include "render/PopulationRenderer.h"

namespace matevo {

// RenderGenomes on `renderer` for genomes of `family` with the base's `kappa` (a genome that
// carries its own kappa genes, for hue variety, is drawn with those: materialOf), at size x size.
RenderGenomes renderGenomesWith(std::shared_ptr<PopulationRenderer> renderer,
                                const MaterialFamily& family, const std::array<double, 3>& kappa,
                                const SceneSettings& scene, int size);

}  // namespace matevo
