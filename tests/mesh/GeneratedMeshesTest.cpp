#include "mesh/GeneratedMeshes.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "mesh/MeshFile.h"

namespace matevo {
namespace {

// Signed volume by the divergence theorem: positive when every triangle is wound
// counter-clockwise seen from outside.
double signedVolume(const Mesh& mesh) {
    double volume = 0.0;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::dvec3 a = mesh.vertices[mesh.indices[i]].position;
        const glm::dvec3 b = mesh.vertices[mesh.indices[i + 1]].position;
        const glm::dvec3 c = mesh.vertices[mesh.indices[i + 2]].position;
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

void expectDrawable(const Mesh& mesh, const char* name) {
    EXPECT_TRUE(validateMesh(mesh, name).ok()) << name;
    EXPECT_GT(signedVolume(mesh), 0.0) << name << ": triangles must face outwards";
    for (const MeshVertex& vertex : mesh.vertices) {
        ASSERT_NEAR(glm::length(vertex.normal), 1.0f, 1e-4f) << name;
        ASSERT_LE(glm::length(vertex.position), 1.0f + 1e-5f) << name << ": fits the unit sphere";
    }
}

TEST(GeneratedMeshes, SphereIsTheUnitSphereWithTheTestSphereMapping) {
    const Mesh sphere = makeSphereMesh(64, 32);
    expectDrawable(sphere, "sphere");
    EXPECT_EQ(sphere.triangleCount(), std::size_t(2 * 64 * 31));
    // Volume of the inscribed polyhedron approaches 4/3 pi from below.
    EXPECT_NEAR(signedVolume(sphere), 4.0 / 3.0 * std::numbers::pi, 0.02);
    for (const MeshVertex& vertex : sphere.vertices) {
        ASSERT_NEAR(glm::length(vertex.position), 1.0f, 1e-5f);
        ASSERT_LT(glm::length(vertex.normal - vertex.position), 1e-5f);
        const glm::vec3 n = vertex.normal;
        // core/scene/SphereMapping.h: u = 0.5 + atan2(x, z) / 2pi, v = acos(y) / pi; the seam
        // column (u = 0 or 1) and the poles (any u) are the only places where u is ambiguous.
        ASSERT_NEAR(vertex.uv.y,
                    std::acos(std::clamp(n.y, -1.0f, 1.0f)) / std::numbers::pi_v<float>, 1e-4f);
        const bool ambiguous =
            std::abs(n.y) > 0.9999f || vertex.uv.x < 1e-6f || vertex.uv.x > 1.0f - 1e-6f;
        if (!ambiguous) {
            ASSERT_NEAR(vertex.uv.x,
                        0.5f + std::atan2(n.x, n.z) / (2.0f * std::numbers::pi_v<float>), 1e-4f);
        }
    }
}

TEST(GeneratedMeshes, BenchmarkMeshesHaveAtLeast20kTrianglesAndFaceOutwards) {
    for (BuiltInMesh kind :
         {BuiltInMesh::Sphere, BuiltInMesh::ShaderBall, BuiltInMesh::TorusKnot}) {
        const Mesh mesh = makeBuiltInMesh(kind);
        const std::string name(toString(kind));
        expectDrawable(mesh, name.c_str());
        EXPECT_GE(mesh.triangleCount(), 20000u) << name;
        EXPECT_EQ(parseBuiltInMesh(name), kind);
    }
}

TEST(GeneratedMeshes, LoadMeshNamesTheBuiltInOnesAndRefusesOtherNames) {
    auto knot = loadMesh("knot");
    ASSERT_TRUE(knot.ok()) << knot.error().message;
    EXPECT_GE(knot->triangleCount(), 20000u);
    auto unknown = loadMesh("teapot");
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().message.find("teapot: not a mesh"), std::string::npos)
        << unknown.error().message;
}

}  // namespace
}  // namespace matevo
