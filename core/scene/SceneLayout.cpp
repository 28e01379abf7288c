#include "scene/SceneLayout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "evolve/Random.h"

namespace matevo {
namespace {

constexpr double kSpacing = 2.3;  // between instance centres in a grid: unit spheres, a gap
constexpr double kFramingPitchDegrees = 25.0;  // the framing camera looks down on the floor

SceneInstance placed(const glm::dvec2& groundPosition, double turnRadians, int index,
                     int materialCount) {
    glm::mat4 transform = glm::translate(
        glm::mat4(1.0f), glm::vec3(float(groundPosition.x), 1.0f, float(groundPosition.y)));
    transform = glm::rotate(transform, float(turnRadians), glm::vec3(0.0f, 1.0f, 0.0f));
    return {transform, std::uint32_t(index % std::max(materialCount, 1))};
}

}  // namespace

std::string_view toString(InstanceLayout layout) {
    return layout == InstanceLayout::Grid ? "grid" : "crowd";
}

std::optional<InstanceLayout> parseInstanceLayout(std::string_view text) {
    if (text == "grid") return InstanceLayout::Grid;
    if (text == "crowd") return InstanceLayout::Crowd;
    return std::nullopt;
}

std::vector<SceneInstance> layoutInstances(int count, InstanceLayout layout, int materialCount,
                                           std::uint64_t seed) {
    Random random(seed);
    std::vector<SceneInstance> instances;
    const int columns = std::max(1, int(std::ceil(std::sqrt(double(count)))));
    const int rows = (count + columns - 1) / std::max(columns, 1);
    if (layout == InstanceLayout::Grid) {
        for (int i = 0; i < count; ++i) {
            const glm::dvec2 position((i % columns - (columns - 1) / 2.0) * kSpacing,
                                      (i / columns - (rows - 1) / 2.0) * kSpacing);
            instances.push_back(placed(position, 0.0, i, materialCount));
        }
        return instances;
    }
    // Crowd: rejection-sampled positions at least 2.05 apart (unit spheres do not touch) in a
    // disc of about 1.7 times the grid's area, every instance turned at random.
    const double radius = kSpacing * std::sqrt(1.7 * double(count) / std::numbers::pi) + 1.0;
    std::vector<glm::dvec2> taken;
    for (int i = 0; i < count; ++i) {
        glm::dvec2 position(0.0);
        for (int attempt = 0; attempt < 1000; ++attempt) {
            position = {(2.0 * random.uniform() - 1.0) * radius,
                        (2.0 * random.uniform() - 1.0) * radius};
            if (glm::length(position) > radius) continue;
            const bool free = std::none_of(
                taken.begin(), taken.end(),
                [&](const glm::dvec2& other) { return glm::length(other - position) < 2.05; });
            if (free) break;
        }
        taken.push_back(position);
        instances.push_back(
            placed(position, 2.0 * std::numbers::pi * random.uniform(), i, materialCount));
    }
    return instances;
}

SceneCamera frameInstances(std::span<const SceneInstance> instances, double aspect,
                           double fieldOfViewDegrees) {
    glm::dvec3 low(0.0), high(0.0);
    for (std::size_t i = 0; i < instances.size(); ++i) {
        const glm::dvec3 centre(instances[i].transform[3]);
        low = i == 0 ? centre : glm::min(low, centre);
        high = i == 0 ? centre : glm::max(high, centre);
    }
    const glm::dvec3 target = 0.5 * (low + high);
    const double tanVertical = std::tan(fieldOfViewDegrees * std::numbers::pi / 360.0);
    const double tanHorizontal = tanVertical * aspect;
    // Every instance's unit bounding sphere inside the view, with a small margin.
    const auto fits = [&](double distance) {
        const SceneCamera camera =
            orbitCamera(target, 0.0, kFramingPitchDegrees, distance, fieldOfViewDegrees);
        const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
        const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
        const glm::dvec3 up = glm::cross(right, forward);
        for (const SceneInstance& instance : instances) {
            const glm::dvec3 offset = glm::dvec3(instance.transform[3]) - camera.position;
            const double depth = glm::dot(offset, forward);
            if (depth < 1.5) return false;
            // Sphere inside a side plane: its centre at least r / cos(half angle) inside.
            const double x = std::abs(glm::dot(offset, right)), y = std::abs(glm::dot(offset, up));
            if (x + std::sqrt(1.0 + tanHorizontal * tanHorizontal) * 1.05 > depth * tanHorizontal ||
                y + std::sqrt(1.0 + tanVertical * tanVertical) * 1.05 > depth * tanVertical)
                return false;
        }
        return true;
    };
    double near = 1.0, far = 4.0;
    while (!fits(far) && far < 1e5) far *= 2.0;
    for (int step = 0; step < 40; ++step) {
        const double middle = 0.5 * (near + far);
        (fits(middle) ? far : near) = middle;
    }
    return orbitCamera(target, 0.0, kFramingPitchDegrees, far, fieldOfViewDegrees);
}

SceneCamera orbitCamera(const glm::dvec3& target, double yawDegrees, double pitchDegrees,
                        double distance, double fieldOfViewDegrees) {
    const double yaw = yawDegrees * std::numbers::pi / 180.0;
    const double pitch = pitchDegrees * std::numbers::pi / 180.0;
    const glm::dvec3 offset(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                            std::cos(yaw) * std::cos(pitch));
    return {target + distance * offset, target, fieldOfViewDegrees};
}

std::optional<std::size_t> pickInstance(const SceneCamera& camera, double aspect,
                                        const glm::dvec2& ndc,
                                        std::span<const SceneInstance> instances) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tanHalfFov = std::tan(camera.fieldOfViewDegrees * std::numbers::pi / 360.0);
    const glm::dvec3 direction =
        glm::normalize(forward + ndc.x * tanHalfFov * aspect * right + ndc.y * tanHalfFov * up);
    std::optional<std::size_t> nearest;
    double nearestDistance = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < instances.size(); ++i) {
        const glm::dvec3 toCentre = glm::dvec3(instances[i].transform[3]) - camera.position;
        const double along = glm::dot(toCentre, direction);
        const double missDistance2 = glm::dot(toCentre, toCentre) - along * along;
        if (along <= 0.0 || missDistance2 > 1.0) continue;
        const double distance = along - std::sqrt(1.0 - missDistance2);
        if (distance < nearestDistance) {
            nearestDistance = distance;
            nearest = i;
        }
    }
    return nearest;
}

}  // namespace matevo
