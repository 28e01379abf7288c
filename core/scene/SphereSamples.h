#pragma once
// Where the test sphere is shaded in an image of size x size (docs/scene.md): for each covered
// pixel, the points its radiance is the mean of (the pixel centre when all 2 x 2 subsamples hit,
// else the subsamples that hit) and its coverage. It depends on the camera and the size only, so
// every material of a batch shares it: the CPU renderer traces it per image, the GPU renderer
// once per camera and size and then shades these points for every material.
#include <vector>

#include <glm/vec3.hpp>

#include "scene/SceneSettings.h"

namespace matevo {

// Subsamples per pixel side (2 x 2 per pixel).
constexpr int kSubsamplesPerAxis = 2;
constexpr int kSubsamplesPerPixel = kSubsamplesPerAxis * kSubsamplesPerAxis;
// A pixel is shaded at its centre when every subsample hits, else at the ones that hit.
constexpr int kMaxPointsPerPixel = kSubsamplesPerPixel - 1;

struct SphereSurfacePoint {
    glm::dvec3 normal;    // unit, world space
    glm::dvec3 toViewer;  // unit, from the point towards the camera
};

struct SpherePixel {
    int x = 0;
    int y = 0;            // down from the top row
    int firstSample = 0;  // into SphereSamples::samples
    int sampleCount = 0;  // >= 1
    int hits = 0;         // subsamples that hit: coverage alpha = hits / kSubsamplesPerPixel
};

struct SphereSamples {
    int size = 0;
    // Covered pixels only (the rest are background), by point count: first those shaded at
    // one point (nearly all), then the silhouette's of two and three points, so that
    // neighbours in the list do the same work (a GPU runs them in lockstep).
    std::vector<SpherePixel> pixels;
    std::vector<SphereSurfacePoint> samples;
};

SphereSamples traceSphereSamples(const SceneSettings& scene, int size);

}  // namespace matevo
