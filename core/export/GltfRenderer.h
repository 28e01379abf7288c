#pragma once
// Renders a glTF material (GltfBrdf.h) in the paper's test scene, exactly as the Belcour
// materials are rendered (scene/SphereRenderer.h): one directional light through the BRDF plus the
// uniform environment (the ambient mode's) through the directional albedo, the scene's textures at
// the sphere's UVs.
// The albedo is tabulated per material over the view cosine (and the roughness texel when a
// roughness texture is used); it is affine in the base colour, so the table keeps the values for
// base colour 0 and 1 and the texture's colour is applied per point without loss.
#include "common/Image.h"
#include "export/GltfMaterial.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo {

// How finely the albedo is tabulated: Draft for the many renders of a fit (about 1 % albedo
// error), Reference for the renders whose ΔE00 is reported.
enum class GltfRenderQuality { Draft, Reference };

Image renderGltfSphere(const GltfMaterial& material, const SceneTextures& textures,
                       const SceneSettings& scene, int size,
                       GltfRenderQuality quality = GltfRenderQuality::Reference);

}  // namespace matevo
