#pragma once
// A format a material is delivered in (glTF: export/GltfDelivery.h), as the delivery check of a
// variant set sees it (variants/DeliveryCheck.h): each genome's delivered look, the way
// RenderGenomes gives matevo's own render. Here, below both, so that a format can offer itself
// to the check without either knowing the other.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "common/Image.h"
#include "common/Result.h"
#include "genome/Genome.h"

namespace matevo {

struct DeliveryFormat {
    std::string name;  // "gltf", for reports
    // Each genome's delivered look at the output size, by conversion `attempt` (0: the ordinary
    // conversion; each later one spends more effort). The same genome and attempt give the
    // same image every time.
    std::function<Result<std::vector<Image>>(std::span<const Genome> genomes, int attempt)> render;
    int attempts = 2;
    // The conversion's goal: mean ΔE00 between a delivered look and matevo's render of it.
    double goalDeltaE = 2.0;
};

}  // namespace matevo
