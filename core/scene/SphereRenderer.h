#pragma once
// The CPU reference renderer of the paper's test scene (§5); the Vulkan renderer must match it.
//
// Scene (docs/scene.md): a unit sphere at the origin; a pinhole camera at
// SceneSettings::cameraPosition looking at the origin, +y up, vertical field of view
// fieldOfViewDegrees, square image. Each pixel takes 2 x 2 subsamples at offsets (0.25, 0.75);
// a subsample's ray hits the sphere or not, alpha = the fraction that hit (coverage). RGB, not
// premultiplied: interior pixels (every subsample hit) are shaded once at the pixel centre,
// silhouette pixels take the mean radiance of their hits; the background is (0, 0, 0, 0).
// Shading at a hit with normal n, view v, light direction l (normalised lightDirection):
//   L = f_r(v, l) * lightRadiance * max(0, n.l) + (e_coat + e_base) * ambientRadiance(scene)
//       + e_coat * P(r, alpha_coat) + e_base * P(r, alpha_base)
// (the ambient term is zero unless in the ambient mode, SceneSettings.h) where P is the
// prefiltered environment of SceneTextures (the environment mode's) around the mirror
// direction r (core/scene/PrefilteredEnvironment.h),
// with the lobes at cos_view = n.v (Forward model) from the material's LobeTable (the adding
// loop interpolated over cos_view and the roughness texel), textures sampled at sphereUv(n).
// Output is linear RGB: no tone mapping, no exposure.
#include <functional>

#include <glm/vec3.hpp>

#include "common/Image.h"
#include "material/FgdTables.h"
#include "material/LobeTable.h"
#include "material/MaterialInstance.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo {

// The scene's picture for any surface model (the glTF BRDF of core/export, for one): the same
// camera, subsamples, coverage and threads, with `radiance(normal, toViewer)` giving the light
// that leaves a sphere point towards the camera (world space, unit vectors).
using SphereRadiance =
    std::function<glm::dvec3(const glm::dvec3& normal, const glm::dvec3& toViewer)>;
Image renderSphereImage(const SceneSettings& scene, int size, const SphereRadiance& radiance);

// Multi-threaded over fixed row chunks; the result does not depend on the thread count.
Image renderSphereCpu(const MaterialInstance& material, const SceneTextures& textures,
                      const SceneSettings& scene, int size, const FgdTables& tables,
                      const LobeTableShape& shape = {});

// The reference that the LobeTable approximates: the adding loop at every subsample (tens of
// times slower), on any InterfaceAlbedo (the tables, or IntegratedAlbedo for the reference of
// the tables themselves) and with any AddingOptions. Tests and the BSDF accuracy bench use it.
Image renderSphereCpuExact(const MaterialInstance& material, const SceneTextures& textures,
                           const SceneSettings& scene, int size, const InterfaceAlbedo& albedo,
                           const AddingOptions& options = {});

// The same as renderSphereCpu with the process-wide tables (built or read from the cache on first
// use).
Image renderSphereCpu(const MaterialInstance& material, const SceneTextures& textures,
                      const SceneSettings& scene, int size);

}  // namespace matevo
