#pragma once
// The mesh cut into clusters of a few dozen neighbouring triangles, each with a bounding sphere
// and a cone that holds its face normals, so that a whole cluster that faces away from the
// viewer is dropped before the GPU sees it (back-face culling per cluster). No triangle is
// simplified or removed: a cluster is dropped only when every one of its triangles faces away,
// which is exactly what per-triangle back-face culling would have dropped.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "mesh/Mesh.h"

namespace matevo {

struct MeshCluster {
    glm::vec3 center{0.0f};  // bounding sphere of the cluster's triangles
    float radius = 0.0f;
    glm::vec3 coneAxis{0.0f, 1.0f, 0.0f};  // every face normal lies within the cone's half angle
    float coneCos = -1.0f;                 // cos and sin of that half angle; coneCos <= 0: the
    float coneSin = 0.0f;                  // normals span a hemisphere, never culled
};

struct ClusteredMesh {
    // The same triangles (and vertices), reordered so that cluster c holds triangles
    // [c * kClusterTriangles, (c + 1) * kClusterTriangles); the last may hold fewer.
    Mesh mesh;
    std::vector<MeshCluster> clusters;
};

inline constexpr std::uint32_t kClusterTriangles = 64;

// Triangles are grouped by the direction of their face normal (cells of about 20 degrees),
// then along a Morton curve through their centroids, so a cluster is a patch with similar
// normals.
ClusteredMesh clusterTriangles(const Mesh& mesh);

// True when every triangle of the cluster, placed by `transform` (rotation, uniform scale,
// translation), faces away from a viewer at `viewer`: the viewer lies behind the plane of each
// of them. Conservative: a cluster with any triangle facing the viewer is never reported.
bool facesAwayFrom(const MeshCluster& cluster, const glm::mat4& transform,
                   const glm::dvec3& viewer);

}  // namespace matevo
