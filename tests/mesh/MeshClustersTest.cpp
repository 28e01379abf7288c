#include "mesh/MeshClusters.h"

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "mesh/GeneratedMeshes.h"

namespace matevo {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::vector<Triangle> trianglesOf(const Mesh& mesh) {
    std::vector<Triangle> triangles;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
        triangles.push_back({mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
    std::sort(triangles.begin(), triangles.end());
    return triangles;
}

// Clustering reorders triangles and nothing else: the same vertices, the same triangles with
// the same winding, and one cluster per kClusterTriangles of them.
TEST(MeshClusters, KeepEveryTriangleAndItsWinding) {
    const Mesh mesh = makeShaderBallMesh();
    const ClusteredMesh clustered = clusterTriangles(mesh);
    EXPECT_EQ(clustered.mesh.vertices.size(), mesh.vertices.size());
    EXPECT_EQ(trianglesOf(clustered.mesh), trianglesOf(mesh));
    EXPECT_EQ(clustered.clusters.size(),
              (mesh.triangleCount() + kClusterTriangles - 1) / kClusterTriangles);
}

// The cone test is conservative: whenever it says a cluster faces away from a viewer, the
// viewer lies behind the plane of every one of its triangles; and it does drop clusters.
TEST(MeshClusters, ClustersReportedFacingAwayHaveOnlyBackFaces) {
    for (const Mesh& mesh : {makeShaderBallMesh(), makeTorusKnotMesh(), makeSphereMesh(64, 32)}) {
        const ClusteredMesh clustered = clusterTriangles(mesh);
        std::mt19937 random(7);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        std::size_t tested = 0, culled = 0;
        for (int placement = 0; placement < 20; ++placement) {
            const glm::mat4 transform = glm::scale(
                glm::rotate(
                    glm::translate(glm::mat4(1.0f), glm::vec3(unit(random), 0.0f, unit(random))),
                    float(3.0 * unit(random)), glm::vec3(0.0f, 1.0f, 0.0f)),
                glm::vec3(0.8f));
            // Viewers near (1.5 units) and far (up to 12) from the instance.
            const glm::dvec3 viewer =
                glm::normalize(glm::dvec3(unit(random), unit(random), unit(random))) *
                (1.5 + 10.0 * (unit(random) + 1.0) / 2.0);
            for (std::size_t c = 0; c < clustered.clusters.size(); ++c) {
                ++tested;
                if (!facesAwayFrom(clustered.clusters[c], transform, viewer)) continue;
                ++culled;
                const std::size_t end =
                    std::min(clustered.mesh.triangleCount(), (c + 1) * kClusterTriangles);
                for (std::size_t t = c * kClusterTriangles; t < end; ++t) {
                    std::array<glm::dvec3, 3> corner;
                    for (int k = 0; k < 3; ++k)
                        corner[std::size_t(k)] = glm::dvec3(
                            transform *
                            glm::vec4(clustered.mesh
                                          .vertices[clustered.mesh.indices[t * 3 + std::size_t(k)]]
                                          .position,
                                      1.0f));
                    const glm::dvec3 normal =
                        glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
                    ASSERT_LE(glm::dot(normal, viewer - corner[0]), 0.0)
                        << "cluster " << c << " holds a triangle facing the viewer";
                }
            }
        }
        EXPECT_GT(double(culled), 0.2 * double(tested)) << "about half the clusters face away";
    }
}

}  // namespace
}  // namespace matevo
