#include "scene/PrefilteredEnvironment.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <glm/geometric.hpp>

#include "common/ParallelFor.h"
#include "material/Ggx.h"
#include "scene/LatLong.h"
#include "scene/SceneTextures.h"

namespace matevo {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 toVector(const std::array<double, 3>& values) {
    return {values[0], values[1], values[2]};
}

glm::dvec3 sampleLatLong(const Image& image, const glm::dvec3& direction) {
    const glm::dvec2 uv = latLongUv(direction);
    return toVector(sampleTexture(image, uv.x, uv.y));
}

// Van der Corput radical inverse in base 2: the second coordinate of the Hammersley set.
double radicalInverse(std::uint32_t bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return double(bits) * 2.3283064365386963e-10;
}

// Box-filtered copies of the source, halving down to a few texels: a wide sample reads a
// coarse level so that few samples suffice (filtered importance sampling, Krivanek & Colbert
// 2008).
struct SourcePyramid {
    std::vector<Image> levels;

    explicit SourcePyramid(const Image& latLong, int baseWidth) {
        const int width = std::min(latLong.width, baseWidth);
        levels.push_back(downsample(latLong, width, std::max(width / 2, 1)));
        while (levels.back().width > 8)
            levels.push_back(downsample(levels.back(), levels.back().width / 2,
                                        std::max(levels.back().height / 2, 1)));
    }

    // Radiance towards `direction` from the level whose texels cover `solidAngle`.
    glm::dvec3 radiance(const glm::dvec3& direction, double solidAngle) const {
        const Image& base = levels.front();
        const double texelSolidAngle = 4.0 * kPi / double(base.width * base.height);
        const double level = std::clamp(0.5 * std::log2(solidAngle / texelSolidAngle), 0.0,
                                        double(levels.size() - 1));
        const auto lower = std::size_t(level);
        const std::size_t upper = std::min(lower + 1, levels.size() - 1);
        const double weight = level - double(lower);
        return (1.0 - weight) * sampleLatLong(levels[lower], direction) +
               weight * sampleLatLong(levels[upper], direction);
    }
};

// Orthonormal tangent frame around a unit direction.
void tangentFrame(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    const glm::dvec3 helper = std::abs(n.y) < 0.999 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    t = glm::normalize(glm::cross(helper, n));
    b = glm::cross(n, t);
}

glm::dvec3 prefilterDirection(const SourcePyramid& source, const glm::dvec3& r, double alpha,
                              int samples) {
    glm::dvec3 t, b;
    tangentFrame(r, t, b);
    glm::dvec3 sum(0.0);
    double weightSum = 0.0;
    for (int i = 0; i < samples; ++i) {
        // GGX half vector with density D(h) (n.h) (Walter et al. 2007), n = v = r.
        const double u1 = (double(i) + 0.5) / double(samples);
        const double u2 = radicalInverse(std::uint32_t(i));
        const double cos2 = (1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1);
        const double cosHalf = std::sqrt(cos2), sinHalf = std::sqrt(std::max(0.0, 1.0 - cos2));
        const double azimuth = 2.0 * kPi * u2;
        const glm::dvec3 h =
            sinHalf * std::cos(azimuth) * t + sinHalf * std::sin(azimuth) * b + cosHalf * r;
        const glm::dvec3 l = 2.0 * cosHalf * h - r;
        const double cosLight = glm::dot(r, l);
        if (cosLight <= 0.0) continue;
        // pdf of l = D(h) (n.h) / (4 v.h) = D(h) / 4 with n = v.
        const double pdf = ggxDistribution(cosHalf, alpha) / 4.0;
        sum += cosLight * source.radiance(l, 1.0 / (double(samples) * pdf));
        weightSum += cosLight;
    }
    return weightSum > 0.0 ? sum / weightSum : glm::dvec3(0.0);
}

double levelAlpha(int level, int levels) {
    const double root = double(level) / double(levels - 1);
    return root * root;
}

Image prefilterLevel(const SourcePyramid& source, double alpha, int width, int samples) {
    Image level(width, std::max(width / 2, 1));
    parallelForChunks(level.height, [&](int y) {
        for (int x = 0; x < level.width; ++x) {
            const glm::dvec3 r = latLongDirection(
                {(x + 0.5) / double(level.width), (y + 0.5) / double(level.height)});
            const glm::dvec3 value = prefilterDirection(source, r, alpha, samples);
            float* texel = level.pixel(x, y);
            for (int c = 0; c < 3; ++c) texel[c] = float(value[c]);
            texel[3] = 1.0f;
        }
    });
    return level;
}

Image upsample(const Image& image, int width, int height) {
    if (image.width == width && image.height == height) return image;
    Image result(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const auto value = sampleTexture(image, (x + 0.5) / width, (y + 0.5) / height);
            float* texel = result.pixel(x, y);
            for (int c = 0; c < 3; ++c) texel[c] = float(value[c]);
            texel[3] = 1.0f;
        }
    return result;
}

}  // namespace

Image downsample(const Image& image, int width, int height) {
    if (image.width == width && image.height == height) return image;
    Image result(width, height);
    for (int y = 0; y < height; ++y) {
        const int rowBegin = y * image.height / height;
        const int rowEnd = std::max((y + 1) * image.height / height, rowBegin + 1);
        for (int x = 0; x < width; ++x) {
            const int columnBegin = x * image.width / width;
            const int columnEnd = std::max((x + 1) * image.width / width, columnBegin + 1);
            double sum[4] = {0, 0, 0, 0};
            for (int sy = rowBegin; sy < rowEnd; ++sy)
                for (int sx = columnBegin; sx < columnEnd; ++sx)
                    for (int c = 0; c < 4; ++c) sum[c] += image.pixel(sx, sy)[c];
            const double count = double((rowEnd - rowBegin) * (columnEnd - columnBegin));
            for (int c = 0; c < 4; ++c) result.pixel(x, y)[c] = float(sum[c] / count);
        }
    }
    return result;
}

double PrefilteredEnvironment::levelOf(double alpha) const {
    return std::sqrt(std::clamp(alpha, 0.0, 1.0)) * double(levels.size() - 1);
}

glm::dvec3 PrefilteredEnvironment::radiance(const glm::dvec3& unitDirection, double alpha) const {
    const double level = levelOf(alpha);
    const auto lower = std::size_t(level);
    const std::size_t upper = std::min(lower + 1, levels.size() - 1);
    const double weight = level - double(lower);
    return (1.0 - weight) * sampleLatLong(levels[lower], unitDirection) +
           weight * sampleLatLong(levels[upper], unitDirection);
}

glm::dvec3 PrefilteredEnvironment::reflected(const LobeSet& lobes, const glm::dvec3& normal,
                                             const glm::dvec3& toViewer) const {
    if (empty()) return glm::dvec3(0.0);
    const glm::dvec3 mirror = 2.0 * glm::dot(normal, toViewer) * normal - toViewer;
    return toVector(lobes.coat.energy) * radiance(mirror, lobes.coat.alpha) +
           toVector(lobes.base.energy) * radiance(mirror, lobes.base.alpha);
}

PrefilteredEnvironment prefilterEnvironment(const Image& latLong,
                                            const PrefilterSettings& settings) {
    const int width = settings.width, height = std::max(settings.width / 2, 1);
    const SourcePyramid source(latLong, 2 * width);
    PrefilteredEnvironment environment;
    // alpha = 0 is a mirror: the environment itself.
    environment.levels.push_back(downsample(source.levels.front(), width, height));
    for (int level = 1; level < settings.levels; ++level) {
        // Wider lobes vary more slowly: compute them at a lower resolution (halving per level,
        // at least 64 texels round) and interpolate up, as the GPU's bilinear fetch would.
        const int levelWidth = std::max(width >> (level - 1), std::min(width, 64));
        // The lower resolution pays for more samples: the same work per level.
        const int scale = width / levelWidth;
        const int samples = std::min(settings.samplesPerTexel * scale * scale, 1024);
        const Image filtered =
            prefilterLevel(source, levelAlpha(level, settings.levels), levelWidth, samples);
        environment.levels.push_back(upsample(filtered, width, height));
    }
    return environment;
}

glm::dvec3 integrateLobeBruteForce(const Image& latLong, const glm::dvec3& r, double alpha) {
    glm::dvec3 sum(0.0);
    double weightSum = 0.0;
    for (int y = 0; y < latLong.height; ++y) {
        const double polar = (y + 0.5) / latLong.height * kPi;
        const double solidAngle =
            (2.0 * kPi / latLong.width) * (kPi / latLong.height) * std::sin(polar);
        for (int x = 0; x < latLong.width; ++x) {
            const glm::dvec3 l = latLongDirection(
                {(x + 0.5) / double(latLong.width), (y + 0.5) / double(latLong.height)});
            const double cosLight = glm::dot(r, l);
            if (cosLight <= 0.0) continue;
            const double weight =
                ggxDistribution(glm::dot(r, glm::normalize(r + l)), alpha) * cosLight * solidAngle;
            const float* texel = latLong.pixel(x, y);
            sum += weight * glm::dvec3(texel[0], texel[1], texel[2]);
            weightSum += weight;
        }
    }
    return sum / weightSum;
}

}  // namespace matevo
