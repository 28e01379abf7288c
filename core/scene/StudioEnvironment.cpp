#include "scene/StudioEnvironment.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "image/ImageFile.h"
#include "material/FgdTableCache.h"
#include "scene/LatLong.h"
#include "scene/StudioEnvironmentCache.h"

namespace matevo {
namespace {

// A rectangular light facing the origin from `towards`, with half-extents given as tangents
// of the half-angles and soft edges.
struct SoftBox {
    glm::dvec3 towards;
    double halfWidth;
    double halfHeight;
    glm::dvec3 radiance;

    glm::dvec3 emitted(const glm::dvec3& direction) const {
        const glm::dvec3 centre = glm::normalize(towards);
        const double facing = glm::dot(direction, centre);
        if (facing <= 0.0) return glm::dvec3(0.0);
        const glm::dvec3 side = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), centre));
        const glm::dvec3 up = glm::cross(centre, side);
        // Gnomonic coordinates on the box's plane, in units of its half-extents.
        const double x = std::abs(glm::dot(direction, side) / facing) / halfWidth;
        const double y = std::abs(glm::dot(direction, up) / facing) / halfHeight;
        const auto edge = [](double t) {  // 1 inside, 0 outside, smooth over the last 15 %
            const double s = std::clamp((1.0 - t) / 0.15, 0.0, 1.0);
            return s * s * (3.0 - 2.0 * s);
        };
        return radiance * (edge(x) * edge(y));
    }
};

glm::dvec3 studioRadiance(const glm::dvec3& d) {
    static const SoftBox boxes[] = {
        {{-0.5, 0.6, 0.62}, 0.35, 0.45, {6.0, 5.8, 5.5}},   // key, where the paper's light is
        {{0.85, 0.2, 0.5}, 0.45, 0.35, {1.3, 1.4, 1.5}},    // fill, cooler
        {{0.15, 0.9, -0.4}, 0.6, 0.25, {3.5, 3.5, 3.5}},    // top rim
        {{-0.75, 0.25, -0.6}, 0.07, 0.6, {4.0, 4.0, 4.0}},  // strip behind, left
    };
    // Backdrop: a grey wall brightest just above the horizon; a darker floor.
    const double height = d.y;
    glm::dvec3 radiance = height >= 0.0
                              ? glm::mix(glm::dvec3(0.22, 0.22, 0.23), glm::dvec3(0.08, 0.08, 0.09),
                                         std::sqrt(height))
                              : glm::mix(glm::dvec3(0.12, 0.11, 0.10), glm::dvec3(0.03, 0.03, 0.03),
                                         std::sqrt(-height));
    for (const SoftBox& box : boxes) radiance += box.emitted(d);
    return radiance;
}

}  // namespace

Image makeStudioEnvironment(int width) {
    Image image(width, std::max(width / 2, 1));
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const glm::dvec3 radiance = studioRadiance(latLongDirection(
                {(x + 0.5) / double(image.width), (y + 0.5) / double(image.height)}));
            float* texel = image.pixel(x, y);
            for (int c = 0; c < 3; ++c) texel[c] = float(radiance[c]);
            texel[3] = 1.0f;
        }
    }
    return image;
}

Result<PrefilteredEnvironment> loadEnvironment(const std::string& studioOrFile,
                                               const PrefilterSettings& settings) {
    if (studioOrFile == "studio")
        return loadOrBuildStudioEnvironment(defaultTableCacheDirectory(), settings).environment;
    auto image = readImage(studioOrFile);
    if (!image) return image.error();
    if (image->width < 2 * image->height - 1 || image->width > 2 * image->height + 1)
        return badInput(studioOrFile + ": not a latitude-longitude environment (" +
                        std::to_string(image->width) + "x" + std::to_string(image->height) +
                        "; width must be twice the height)");
    for (float value : image->rgba)
        if (!std::isfinite(value) || value < 0.0f)
            return badInput(studioOrFile + ": has negative or non-finite radiance");
    return prefilterEnvironment(*image, settings);
}

}  // namespace matevo
