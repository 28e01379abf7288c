// The coarse meshes the Scene window's previews draw: far fewer triangles, the same volume and
// winding, creases kept sharp.
#include "mesh/MeshSimplification.h"

#include <array>
#include <cmath>
#include <map>
#include <utility>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "mesh/GeneratedMeshes.h"

namespace matevo {
namespace {

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

// Whether the surface is closed where the input was: every edge, by its ends' positions, is
// crossed as often in one direction as in the other (no crack, no hole opened).
bool closedByPosition(const Mesh& mesh) {
    using Point = std::array<float, 3>;
    std::map<std::pair<Point, Point>, int> edges;
    const auto point = [&](std::uint32_t index) {
        const glm::vec3 p = mesh.vertices[index].position;
        return Point{p.x, p.y, p.z};
    };
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3)
        for (int k = 0; k < 3; ++k) {
            const Point from = point(mesh.indices[i + std::size_t(k)]);
            const Point to = point(mesh.indices[i + std::size_t((k + 1) % 3)]);
            ++edges[{from, to}];
            --edges[{to, from}];
        }
    for (const auto& [edge, balance] : edges)
        if (balance != 0) return false;
    return true;
}

// A cube of side 2, each face a grid of n x n quads with its own vertices and normal (as a
// file with hard edges has). With n a power of two the faces' edges meet exactly.
Mesh cube(int n) {
    Mesh mesh;
    const glm::vec3 normals[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    for (const glm::vec3& normal : normals) {
        const glm::vec3 u = std::abs(normal.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        const glm::vec3 v = glm::cross(normal, u);
        const auto first = std::uint32_t(mesh.vertices.size());
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const float s = 2.0f * float(i) / float(n) - 1.0f,
                            t = 2.0f * float(j) / float(n) - 1.0f;
                mesh.vertices.push_back(
                    {normal + s * u + t * v, normal, {float(i) / float(n), float(j) / float(n)}});
            }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::uint32_t a = first + std::uint32_t(j * (n + 1) + i);
                const std::uint32_t b = a + 1, c = a + std::uint32_t(n + 1), d = c + 1;
                mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
            }
    }
    return mesh;
}

TEST(MeshSimplification, TheShaderBallKeepsItsShapeWithFarFewerTriangles) {
    const Mesh ball = makeShaderBallMesh();
    const Mesh coarse = simplifyByVertexClustering(ball, 24);
    EXPECT_TRUE(validateMesh(coarse, "coarse").ok());
    EXPECT_LT(coarse.triangleCount() * 4, ball.triangleCount())
        << coarse.triangleCount() << " of " << ball.triangleCount();
    EXPECT_GT(coarse.triangleCount(), 500u);
    // The same solid, wound the same way: its volume within a few per cent.
    EXPECT_NEAR(signedVolume(coarse) / signedVolume(ball), 1.0, 0.05);
    // The ball's seam vertices differ in their last bits, but fall into one cell.
    EXPECT_TRUE(closedByPosition(coarse));
    const float cell = 2.0f / 24.0f;
    for (const MeshVertex& vertex : coarse.vertices) {
        ASSERT_NEAR(glm::length(vertex.normal), 1.0f, 1e-4f);
        ASSERT_LE(glm::length(vertex.position), 1.0f + cell);
    }
}

TEST(MeshSimplification, CreasesKeepTheirOwnNormalsOnOnePosition) {
    const Mesh box = cube(8);
    const Mesh coarse = simplifyByVertexClustering(box, 4);
    ASSERT_GT(coarse.triangleCount(), 0u);
    EXPECT_LT(coarse.triangleCount(), box.triangleCount());
    EXPECT_NEAR(signedVolume(coarse) / signedVolume(box), 1.0, 0.35);
    // Every normal is still one of the faces': none averaged over an edge or a corner.
    for (const MeshVertex& vertex : coarse.vertices) {
        const glm::vec3 n = glm::abs(vertex.normal);
        ASSERT_NEAR(std::max({n.x, n.y, n.z}), 1.0f, 1e-5f)
            << vertex.normal.x << " " << vertex.normal.y << " " << vertex.normal.z;
    }
    // No crack along a crease: the faces' vertices in one cell share their position.
    ASSERT_TRUE(closedByPosition(box));
    EXPECT_TRUE(closedByPosition(coarse));
}

TEST(MeshSimplification, AMeshThatWouldVanishComesBackUnchanged) {
    Mesh tiny;
    tiny.vertices = {{{0, 0, 0}, {0, 0, 1}, {0, 0}},
                     {{1e-3f, 0, 0}, {0, 0, 1}, {1, 0}},
                     {{0, 1e-3f, 0}, {0, 0, 1}, {0, 1}}};
    tiny.indices = {0, 1, 2};
    const Mesh same = simplifyByVertexClustering(tiny, 1);
    EXPECT_EQ(same.indices, tiny.indices);
    EXPECT_EQ(same.vertices.size(), tiny.vertices.size());
    // A finer grid keeps it whole.
    EXPECT_EQ(simplifyByVertexClustering(tiny, 4).triangleCount(), 1u);
}

}  // namespace
}  // namespace matevo
