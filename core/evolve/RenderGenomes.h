#pragma once
// The seam between the algorithms and a renderer: genomes of one material (the caller binds the
// family, kappa, textures, scene and image size, and chooses the back end) in, one sphere image
// per genome out, in order. The experiment scores its runs through it, the image-space fitness
// and the variant search render their candidates through it.
#include <functional>
#include <span>
#include <vector>

#include "common/Image.h"
#include "common/Result.h"
#include "genome/Genome.h"

namespace matevo {

using RenderGenomes = std::function<Result<std::vector<Image>>(std::span<const Genome> genomes)>;

}  // namespace matevo
