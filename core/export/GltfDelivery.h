#pragma once
// glTF as the format a variant set is delivered in (`matevo variants --deliver gltf`; the check
// itself is variants/DeliveryCheck.h): each genome's material is fitted (GltfFit.h) to matevo's
// Belcour render at the fitting size, and the fit is rendered with the glTF BRDF (GltfRenderer.h)
// at the output size, quantised as a PNG holds it: the look the glTF specification defines for
// the exported parameters. Conversion 0 is the export's own fit; conversion 1, the refit, has
// three times the budget and also starts from the target's fit (variants lie near the target).
// The fits are kept, so the files written (fittedSet) hold exactly the fits that were checked.
#include <array>
#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "common/Image.h"
#include "common/Result.h"
#include "evolve/DeliveryFormat.h"
#include "evolve/RenderGenomes.h"
#include "export/ExportSet.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo {

class GltfDelivery {
public:
    static constexpr int kConversions = 2;  // the fit, and one refit

    // `target`: the set's target genome; `belcourAtFitSize` renders genomes at
    // settings.fit.imageSize, unquantised; `baseKappa` is the preset's (a genome with kappa
    // genes carries its own).
    GltfDelivery(const Genome& target, const MaterialFamily& family,
                 const std::array<double, 3>& baseKappa, SceneTextures textures,
                 const SceneSettings& scene, RenderGenomes belcourAtFitSize, int outputSize,
                 const ExportSettings& settings);

    // The delivered look of each genome by conversion `attempt` (0 or 1); fits not made yet
    // are made side by side on the worker threads.
    Result<std::vector<Image>> render(std::span<const Genome> genomes, int attempt);
    // This conversion as the delivery check sees it: "gltf", render(), kConversions, and the
    // fit's goal. It refers to this object, which must outlive it.
    DeliveryFormat format();

    // The target (first, named targetName) and the variants (named as given) with the fits of
    // the conversions that were delivered, ready for writeExport; the report's ΔE00 is the
    // delivered look against `belcour` (the Belcour renders at the output size, target first).
    struct Member {
        std::string name;
        Genome genome;
        int attempt = 0;
        Image belcour;
    };
    Result<FittedSet> fittedSet(const std::vector<Member>& members) const;

private:
    struct Conversion {
        GltfFit fit;
        Image look;
    };
    using Key = std::pair<decltype(Genome::values), int>;  // genes, attempt

    Genome target_;
    MaterialFamily family_;
    std::array<double, 3> baseKappa_;
    SceneTextures textures_;
    SceneSettings scene_;
    RenderGenomes belcourAtFitSize_;
    int outputSize_;
    ExportSettings settings_;
    std::map<Key, Conversion> conversions_;
};

}  // namespace matevo
