#include "mesh/MeshClusters.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

namespace matevo {
namespace {

// Spreads the low 10 bits of v so that two zero bits follow each (a 30-bit Morton code).
std::uint32_t spreadBits(std::uint32_t v) {
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

glm::dvec3 cornerOf(const Mesh& mesh, std::size_t triangle, int corner) {
    return glm::dvec3(mesh.vertices[mesh.indices[triangle * 3 + std::size_t(corner)]].position);
}

// Which of kNormalBins x kNormalBins cells of the octahedral map of directions (Meyer et al.
// 2010) the unit normal falls in: cells of about 20 degrees, so a cluster's cone stays narrow.
constexpr int kNormalBins = 8;
std::uint32_t normalBin(const glm::dvec3& normal) {
    const glm::dvec3 n = normal / (std::abs(normal.x) + std::abs(normal.y) + std::abs(normal.z));
    glm::dvec2 folded(n.x, n.y);
    if (n.z < 0.0)
        folded = (1.0 - glm::abs(glm::dvec2(n.y, n.x))) *
                 glm::dvec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    const glm::ivec2 cell = glm::clamp(glm::ivec2((folded * 0.5 + 0.5) * double(kNormalBins)),
                                       glm::ivec2(0), glm::ivec2(kNormalBins - 1));
    return std::uint32_t(cell.y * kNormalBins + cell.x);
}

MeshCluster boundCluster(const Mesh& mesh, std::size_t first, std::size_t end) {
    glm::dvec3 low(INFINITY), high(-INFINITY), normalSum(0.0);
    std::vector<glm::dvec3> normals;
    for (std::size_t t = first; t < end; ++t) {
        const glm::dvec3 a = cornerOf(mesh, t, 0), b = cornerOf(mesh, t, 1),
                         c = cornerOf(mesh, t, 2);
        for (const glm::dvec3& p : {a, b, c}) {
            low = glm::min(low, p);
            high = glm::max(high, p);
        }
        const glm::dvec3 cross = glm::cross(b - a, c - a);
        const double length = glm::length(cross);
        if (length == 0.0) continue;  // covers no pixel, faces nowhere
        normals.push_back(cross / length);
        normalSum += normals.back();
    }
    MeshCluster cluster;
    const glm::dvec3 center = 0.5 * (low + high);
    double radius = 0.0;
    for (std::size_t t = first; t < end; ++t)
        for (int corner = 0; corner < 3; ++corner)
            radius = std::max(radius, glm::length(cornerOf(mesh, t, corner) - center));
    cluster.center = glm::vec3(center);
    cluster.radius = float(radius * (1.0 + 1e-6));
    const double sumLength = glm::length(normalSum);
    if (normals.empty() || sumLength < 1e-9) return cluster;  // never culled
    const glm::dvec3 axis = normalSum / sumLength;
    double coneCos = 1.0;
    for (const glm::dvec3& normal : normals) coneCos = std::min(coneCos, glm::dot(normal, axis));
    cluster.coneAxis = glm::vec3(axis);
    cluster.coneCos = float(coneCos);
    cluster.coneSin = float(std::sqrt(std::max(0.0, 1.0 - coneCos * coneCos)));
    return cluster;
}

}  // namespace

ClusteredMesh clusterTriangles(const Mesh& mesh) {
    const std::size_t triangles = mesh.triangleCount();
    glm::dvec3 low(INFINITY), high(-INFINITY);
    for (const MeshVertex& vertex : mesh.vertices) {
        low = glm::min(low, glm::dvec3(vertex.position));
        high = glm::max(high, glm::dvec3(vertex.position));
    }
    const glm::dvec3 extent = glm::max(high - low, glm::dvec3(1e-30));
    std::vector<std::uint64_t> keys(triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::dvec3 a = cornerOf(mesh, t, 0), b = cornerOf(mesh, t, 1),
                         c = cornerOf(mesh, t, 2);
        const glm::dvec3 cell =
            glm::clamp((a + b + c) / 3.0 - low, glm::dvec3(0.0), extent) / extent * 1023.0;
        const std::uint32_t morton = spreadBits(std::uint32_t(cell.x)) |
                                     (spreadBits(std::uint32_t(cell.y)) << 1) |
                                     (spreadBits(std::uint32_t(cell.z)) << 2);
        const glm::dvec3 cross = glm::cross(b - a, c - a);
        const double area = glm::length(cross);
        keys[t] = (std::uint64_t(area > 0.0 ? normalBin(cross / area) : 0u) << 32) | morton;
    }
    std::vector<std::size_t> order(triangles);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t x, std::size_t y) { return keys[x] < keys[y]; });

    ClusteredMesh clustered;
    clustered.mesh.vertices = mesh.vertices;
    clustered.mesh.indices.reserve(mesh.indices.size());
    for (std::size_t t : order)
        for (int corner = 0; corner < 3; ++corner)
            clustered.mesh.indices.push_back(mesh.indices[t * 3 + std::size_t(corner)]);
    for (std::size_t first = 0; first < triangles; first += kClusterTriangles)
        clustered.clusters.push_back(
            boundCluster(clustered.mesh, first, std::min(triangles, first + kClusterTriangles)));
    return clustered;
}

bool facesAwayFrom(const MeshCluster& cluster, const glm::mat4& transform,
                   const glm::dvec3& viewer) {
    if (cluster.coneCos <= 0.0f) return false;
    const glm::dmat4 placed(transform);
    const double scale = glm::length(glm::dvec3(placed[0]));
    const glm::dvec3 center = glm::dvec3(placed * glm::dvec4(glm::dvec3(cluster.center), 1.0));
    const glm::dvec3 axis = glm::normalize(glm::dmat3(placed) * glm::dvec3(cluster.coneAxis));
    const glm::dvec3 toCluster = center - viewer;
    const double distance = glm::length(toCluster);
    const double radius = double(cluster.radius) * scale;
    if (distance <= radius) return false;
    // Every direction from the viewer into the bounding sphere lies within angle beta of
    // toCluster (sin beta = radius / distance), every face normal within the cone's half angle
    // theta of the axis. Each triangle faces away when its normal makes less than 90 degrees
    // with the direction to any of its points, which holds for all of them when
    // angle(axis, toCluster) + theta + beta < 90 degrees.
    const double sinBeta = radius / distance;
    const double cosBeta = std::sqrt(1.0 - sinBeta * sinBeta);
    const double cosThetaPlusBeta =
        double(cluster.coneCos) * cosBeta - double(cluster.coneSin) * sinBeta;
    const double sinThetaPlusBeta =
        double(cluster.coneSin) * cosBeta + double(cluster.coneCos) * sinBeta;
    // A small margin keeps triangles within rounding of edge-on (which cover no pixel anyway)
    // out of the argument.
    constexpr double kMargin = 1e-4;
    return cosThetaPlusBeta > kMargin &&
           glm::dot(axis, toCluster) / distance > sinThetaPlusBeta + kMargin;
}

}  // namespace matevo
