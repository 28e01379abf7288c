#include "mesh/MeshSimplification.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "mesh/GeneratedMeshes.h"

namespace matevo {
namespace {

float largestRadius(const Mesh& mesh) {
    float radius = 0.0f;
    for (const MeshVertex& vertex : mesh.vertices)
        radius = std::max(radius, glm::length(vertex.position));
    return radius;
}

// A coarse sphere is still a sphere: fewer triangles, vertices near the unit sphere, normals
// radial, every index in range and no triangle with two corners at one vertex.
TEST(MeshSimplification, ClusteringASphereKeepsItsShapeWithFewerTriangles) {
    const Mesh sphere = makeSphereMesh(128, 64);
    const Mesh coarse = clusterVertices(sphere, 16);
    ASSERT_GT(coarse.triangleCount(), 100u);
    EXPECT_LT(coarse.triangleCount() * 4, sphere.triangleCount());
    for (const MeshVertex& vertex : coarse.vertices) {
        const float radius = glm::length(vertex.position);
        EXPECT_NEAR(radius, 1.0f, 0.05f);
        EXPECT_GT(glm::dot(vertex.normal, vertex.position / radius), 0.95f);
        EXPECT_NEAR(glm::length(vertex.normal), 1.0f, 1e-5f);
    }
    for (std::size_t t = 0; t < coarse.indices.size(); t += 3) {
        for (int corner = 0; corner < 3; ++corner)
            ASSERT_LT(coarse.indices[t + corner], coarse.vertices.size());
        EXPECT_NE(coarse.indices[t], coarse.indices[t + 1]);
        EXPECT_NE(coarse.indices[t + 1], coarse.indices[t + 2]);
        EXPECT_NE(coarse.indices[t], coarse.indices[t + 2]);
    }
    EXPECT_TRUE(validateMesh(coarse, "coarse sphere").ok());
}

// Triangles stay counter-clockwise seen from outside: the face normal points away from the
// centre for (nearly) every triangle of a coarse sphere, so back-face culling keeps the front.
TEST(MeshSimplification, ClusteringKeepsTheWindingOfTheTriangles) {
    const Mesh coarse = clusterVertices(makeSphereMesh(128, 64), 12);
    std::size_t outward = 0;
    for (std::size_t t = 0; t < coarse.indices.size(); t += 3) {
        const glm::vec3 a = coarse.vertices[coarse.indices[t]].position;
        const glm::vec3 b = coarse.vertices[coarse.indices[t + 1]].position;
        const glm::vec3 c = coarse.vertices[coarse.indices[t + 2]].position;
        if (glm::dot(glm::cross(b - a, c - a), a + b + c) > 0.0f) ++outward;
    }
    EXPECT_GE(double(outward), 0.99 * double(coarse.triangleCount()));
}

// Each level has fewer than half the triangles of the one before, the first is the mesh
// itself, and none grows beyond the mesh's bounds.
TEST(MeshSimplification, LevelsHalveTheTrianglesDownToAFewHundred) {
    for (BuiltInMesh builtIn : {BuiltInMesh::Sphere, BuiltInMesh::ShaderBall,
                                BuiltInMesh::TorusKnot}) {
        const Mesh mesh = makeBuiltInMesh(builtIn);
        const std::vector<Mesh> levels = levelsOfDetail(mesh);
        ASSERT_GE(levels.size(), 3u) << toString(builtIn);
        EXPECT_EQ(levels.front().triangleCount(), mesh.triangleCount());
        for (std::size_t i = 1; i < levels.size(); ++i) {
            EXPECT_LT(levels[i].triangleCount() * 2, levels[i - 1].triangleCount() + 1)
                << toString(builtIn) << " level " << i;
            EXPECT_LE(largestRadius(levels[i]), largestRadius(mesh) + 1e-4f);
            EXPECT_TRUE(validateMesh(levels[i], "level").ok());
        }
        EXPECT_LT(levels.back().triangleCount(), 1500u) << toString(builtIn);
    }
}

}  // namespace
}  // namespace matevo
