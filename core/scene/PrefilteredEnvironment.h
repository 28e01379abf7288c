#pragma once
// Image-based lighting from a latitude-longitude HDR environment, prefiltered for GGX lobes
// (the split-sum approximation, Karis 2013): a Belcour lobe of energy E and roughness alpha
// reflects E * P(r, alpha) from the environment, where r is the mirror direction of the view
// and P the environment averaged under the GGX lobe around r, weighted by the cosine to the
// light (with the usual n = v = r assumption):
//   P(r, alpha) = Int L(l) D(h) (r.l) dl / Int D(h) (r.l) dl   over r.l > 0, h = (r + l)/|r + l|
// Under a uniform environment L0 this is exactly L0, so the term reduces to today's
// (e_coat + e_base) * ambient. P is tabulated at `levels` roughness nodes alpha_k = (k / (levels
// - 1))^2 (denser where the lobe is narrow), each a lat-long image of the same size, and
// interpolated linearly in u, v and sqrt(alpha) — on the GPU by one 3D texture fetch.
#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "common/Image.h"
#include "material/LayeredLobes.h"

namespace matevo {

struct PrefilterSettings {
    int width = 256;  // of every level; height = width / 2
    int levels = 7;
    // GGX importance samples per texel at full resolution, each read from a filtered source
    // level; levels computed at a lower resolution take proportionally more.
    int samplesPerTexel = 48;
};

struct PrefilteredEnvironment {
    std::vector<Image> levels;  // empty: no environment

    bool empty() const { return levels.empty(); }
    // sqrt(alpha) * (levels - 1): the level coordinate of a lobe.
    double levelOf(double alpha) const;
    // P(direction, alpha), interpolated as the GPU's trilinear fetch does.
    glm::dvec3 radiance(const glm::dvec3& unitDirection, double alpha) const;
    // What the lobes reflect towards the viewer: each lobe's energy times P around the mirror
    // direction of toViewer about normal (shaders/SceneLighting.glsl); zero when empty.
    glm::dvec3 reflected(const LobeSet& lobes, const glm::dvec3& normal,
                         const glm::dvec3& toViewer) const;
};

// Deterministic for the same image and settings (quasi-random samples, fixed chunks).
PrefilteredEnvironment prefilterEnvironment(const Image& latLong,
                                            const PrefilterSettings& settings = {});

// The reference that prefilterEnvironment approximates: the integral above by quadrature over
// every texel of `latLong` (slow; only tests use it).
glm::dvec3 integrateLobeBruteForce(const Image& latLong, const glm::dvec3& unitDirection,
                                   double alpha);

// The box average of the texels that fall into each output texel.
Image downsample(const Image& image, int width, int height);

}  // namespace matevo
