#pragma once
// Chooses the glTF parameters (GltfMaterial.h) whose render in our scene is closest to our
// Belcour render of the same material, by mean CIEDE2000 over the sphere: glTF cannot express the
// Belcour stack (its coat IOR is fixed at 1.5, the coat does not absorb, alpha = roughness^2), so
// a parameter-by-parameter conversion would be wrong by more than it needs to be.
#include <span>

#include "common/Image.h"
#include "export/GltfMaterial.h"
#include "material/MaterialInstance.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo {

struct GltfFitSettings {
    int imageSize = 64;        // side of the images compared while fitting
    int maxEvaluations = 900;  // renders, over all starts
    // The export's goal; a fit past it gets one more round (half the budget again).
    double goalMeanDeltaE00 = 2.0;
};

struct GltfFit {
    GltfMaterial material;
    double meanDeltaE00 = 0.0;  // at the fitting size, against `target`
    int evaluations = 0;
};

// The largest ior a fit of `family` writes (the smallest is 1: no dielectric F0). A dielectric
// base: the largest index Table 2 gives that base (eta2), the range the reference model is
// defined on. A conductor base has no dielectric index: the dielectric part of its glTF fit
// stands in for coat and medium, where an ior would stand in for something else (often the coat's
// reflection, which glTF fixes at ior 1.5 and clients read differently); it stays at glTF's 1.5,
// so no ior is written.
double maximumFittedIor(const MaterialFamily& family);

// `target` is the Belcour render of `material` at settings.imageSize (either back end).
// `moreStarts`: materials the fit also starts from (e.g. a refit of a variant starts from its
// target's fit too); the budget is shared evenly by every start. Deterministic.
GltfFit fitGltfMaterial(const MaterialInstance& material, const Image& target,
                        const SceneTextures& textures, const SceneSettings& scene,
                        const GltfFitSettings& settings = {},
                        std::span<const GltfMaterial> moreStarts = {});

}  // namespace matevo
