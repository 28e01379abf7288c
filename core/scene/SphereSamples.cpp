#include "scene/SphereSamples.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "common/ParallelFor.h"

namespace matevo {
namespace {

constexpr int kRowsPerChunk = 8;

glm::dvec3 toVector(const std::array<double, 3>& values) {
    return {values[0], values[1], values[2]};
}

struct Camera {
    glm::dvec3 position;
    glm::dvec3 forward;
    glm::dvec3 right;
    glm::dvec3 up;
    double tanHalfFov;

    explicit Camera(const SceneSettings& scene)
        : position(toVector(scene.cameraPosition)),
          forward(glm::normalize(-position)),
          right(glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)))),
          up(glm::cross(right, forward)),
          tanHalfFov(std::tan(scene.fieldOfViewDegrees * std::numbers::pi / 360.0)) {}

    // Ray direction through image position (x, y) in pixels, y down.
    glm::dvec3 direction(double x, double y, int size) const {
        const double ndcX = 2.0 * x / size - 1.0;
        const double ndcY = 1.0 - 2.0 * y / size;
        return glm::normalize(forward + ndcX * tanHalfFov * right + ndcY * tanHalfFov * up);
    }
};

// Distance along the ray to the unit sphere at the origin, or a negative value for a miss.
double hitUnitSphere(const glm::dvec3& origin, const glm::dvec3& direction) {
    const double b = glm::dot(origin, direction);
    const double discriminant = b * b - (glm::dot(origin, origin) - 1.0);
    if (discriminant < 0.0) return -1.0;
    return -b - std::sqrt(discriminant);
}

// Where the ray through image position (x, y) meets the sphere.
std::optional<SphereSurfacePoint> traceSphere(const Camera& camera, double x, double y, int size) {
    const glm::dvec3 direction = camera.direction(x, y, size);
    const double distance = hitUnitSphere(camera.position, direction);
    if (distance <= 0.0) return std::nullopt;
    return SphereSurfacePoint{glm::normalize(camera.position + distance * direction), -direction};
}

}  // namespace

SphereSamples traceSphereSamples(const SceneSettings& scene, int size) {
    const Camera camera(scene);
    // Rows are traced in parallel chunks; each chunk groups its pixels and their points by
    // point count, and the list is the concatenation by count, then by chunk (so the result
    // does not depend on the thread count).
    struct Chunk {
        std::array<std::vector<SpherePixel>, kMaxPointsPerPixel + 1> pixels;
        std::array<std::vector<SphereSurfacePoint>, kMaxPointsPerPixel + 1> samples;
    };
    std::vector<Chunk> chunks(std::size_t((size + kRowsPerChunk - 1) / kRowsPerChunk));
    parallelForChunks(int(chunks.size()), [&](int chunkIndex) {
        Chunk& chunk = chunks[std::size_t(chunkIndex)];
        const int lastRow = std::min(size, (chunkIndex + 1) * kRowsPerChunk);
        for (int y = chunkIndex * kRowsPerChunk; y < lastRow; ++y) {
            for (int x = 0; x < size; ++x) {
                std::array<SphereSurfacePoint, kSubsamplesPerPixel> hitPoints;
                int hits = 0;
                for (int sy = 0; sy < kSubsamplesPerAxis; ++sy) {
                    for (int sx = 0; sx < kSubsamplesPerAxis; ++sx) {
                        const auto point = traceSphere(camera, x + (sx + 0.5) / kSubsamplesPerAxis,
                                                       y + (sy + 0.5) / kSubsamplesPerAxis, size);
                        if (point) hitPoints[hits++] = *point;
                    }
                }
                if (hits == 0) continue;
                // Interior pixels shade once, at the centre: shading dominates the cost and
                // the radiance barely varies across one pixel; the silhouette keeps its
                // subsamples.
                const auto centre = hits == kSubsamplesPerPixel
                                        ? traceSphere(camera, x + 0.5, y + 0.5, size)
                                        : std::nullopt;
                const int count = centre ? 1 : hits;
                auto& samples = chunk.samples[std::size_t(count)];
                chunk.pixels[std::size_t(count)].push_back(
                    {x, y, int(samples.size()), count, hits});
                if (centre)
                    samples.push_back(*centre);
                else
                    samples.insert(samples.end(), hitPoints.begin(), hitPoints.begin() + hits);
            }
        }
    });
    SphereSamples result;
    result.size = size;
    for (std::size_t count = 1; count <= kMaxPointsPerPixel; ++count) {
        for (const Chunk& chunk : chunks) {
            const int offset = int(result.samples.size());
            for (SpherePixel pixel : chunk.pixels[count]) {
                pixel.firstSample += offset;
                result.pixels.push_back(pixel);
            }
            result.samples.insert(result.samples.end(), chunk.samples[count].begin(),
                                  chunk.samples[count].end());
        }
    }
    return result;
}

}  // namespace matevo
