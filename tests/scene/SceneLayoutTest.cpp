#include "scene/SceneLayout.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace matevo {
namespace {

glm::dvec3 centre(const SceneInstance& instance) { return glm::dvec3(instance.transform[3]); }

// Where an instance's centre lands in the image, in ndc (x right, y up).
glm::dvec2 project(const SceneCamera& camera, double aspect, const glm::dvec3& point) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const glm::dvec3 offset = point - camera.position;
    const double tanHalfFov = std::tan(camera.fieldOfViewDegrees * 3.14159265358979 / 360.0);
    const double depth = glm::dot(offset, forward);
    return {glm::dot(offset, right) / (depth * tanHalfFov * aspect),
            glm::dot(offset, up) / (depth * tanHalfFov)};
}

TEST(SceneLayout, CrowdIsDeterministicAndNeverOverlaps) {
    const auto crowd = layoutInstances(40, InstanceLayout::Crowd, 7, 3);
    ASSERT_EQ(crowd.size(), 40u);
    for (std::size_t i = 0; i < crowd.size(); ++i) {
        EXPECT_EQ(crowd[i].material, i % 7);
        for (std::size_t j = 0; j < i; ++j)
            EXPECT_GE(glm::length(centre(crowd[i]) - centre(crowd[j])), 2.0) << i << " " << j;
    }
    const auto again = layoutInstances(40, InstanceLayout::Crowd, 7, 3);
    const auto other = layoutInstances(40, InstanceLayout::Crowd, 7, 4);
    EXPECT_EQ(centre(again[5]), centre(crowd[5]));
    EXPECT_NE(centre(other[5]), centre(crowd[5]));
}

TEST(SceneLayout, FramingShowsEveryInstanceAndPickingFindsThem) {
    for (InstanceLayout layout : {InstanceLayout::Grid, InstanceLayout::Crowd}) {
        const auto instances = layoutInstances(25, layout, 25);
        const double aspect = 16.0 / 9.0;
        const SceneCamera camera = frameInstances(instances, aspect);
        for (std::size_t i = 0; i < instances.size(); ++i) {
            const glm::dvec2 ndc = project(camera, aspect, centre(instances[i]));
            EXPECT_LT(std::abs(ndc.x), 1.0) << toString(layout) << " instance " << i;
            EXPECT_LT(std::abs(ndc.y), 1.0) << toString(layout) << " instance " << i;
            // The ray through an instance's centre meets it, or one standing in front of it.
            const auto picked = pickInstance(camera, aspect, ndc, instances);
            ASSERT_TRUE(picked.has_value());
            EXPECT_LE(glm::length(centre(instances[*picked]) - camera.position),
                      glm::length(centre(instances[i]) - camera.position) + 1e-9);
        }
        EXPECT_FALSE(pickInstance(camera, aspect, {0.999, 0.999}, instances).has_value());
    }
}

}  // namespace
}  // namespace matevo
