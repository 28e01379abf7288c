#include "mesh/MeshSimplification.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace matevo {
namespace {

constexpr std::size_t kFewestTriangles = 300;

// 0..5: the axis and sign of the normal's largest component.
std::uint64_t dominantDirection(const glm::vec3& normal) {
    const glm::vec3 magnitude = glm::abs(normal);
    const int axis = magnitude.x >= magnitude.y && magnitude.x >= magnitude.z ? 0
                     : magnitude.y >= magnitude.z                             ? 1
                                                                              : 2;
    return std::uint64_t(2 * axis + (normal[axis] < 0.0f ? 1 : 0));
}

std::uint64_t textureQuadrant(const glm::vec2& uv) {
    return std::uint64_t(uv.x >= 0.5f) + 2 * std::uint64_t(uv.y >= 0.5f);
}

struct Sum {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
    glm::vec2 uv{0.0f};
    int count = 0;
};

}  // namespace

Mesh clusterVertices(const Mesh& mesh, int cellsPerAxis) {
    glm::vec3 lowest(INFINITY), highest(-INFINITY);
    for (const MeshVertex& vertex : mesh.vertices) {
        lowest = glm::min(lowest, vertex.position);
        highest = glm::max(highest, vertex.position);
    }
    const float cells = float(std::max(cellsPerAxis, 1));
    const glm::vec3 cellSize = glm::max((highest - lowest) / cells, glm::vec3(1e-12f));
    auto cellOf = [&](const glm::vec3& position) {
        const glm::vec3 index =
            glm::clamp(glm::floor((position - lowest) / cellSize), glm::vec3(0.0f),
                       glm::vec3(cells - 1.0f));
        return std::uint64_t(index.x) + 1024 * (std::uint64_t(index.y) + 1024 * std::uint64_t(index.z));
    };

    // Each vertex's cell (for positions) and its cluster (cell, normal direction, UV quadrant).
    std::unordered_map<std::uint64_t, Sum> cellSums;
    std::unordered_map<std::uint64_t, std::uint32_t> clusterIndex;
    std::vector<Sum> clusterSums;
    std::vector<std::uint64_t> clusterCell;
    std::vector<std::uint32_t> vertexCluster(mesh.vertices.size());
    std::vector<std::uint64_t> vertexCell(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const MeshVertex& vertex = mesh.vertices[i];
        const std::uint64_t cell = cellOf(vertex.position);
        Sum& cellSum = cellSums[cell];
        cellSum.position += vertex.position;
        ++cellSum.count;
        const std::uint64_t key =
            cell * 24 + dominantDirection(vertex.normal) * 4 + textureQuadrant(vertex.uv);
        auto [found, inserted] = clusterIndex.try_emplace(key, std::uint32_t(clusterSums.size()));
        if (inserted) {
            clusterSums.emplace_back();
            clusterCell.push_back(cell);
        }
        Sum& cluster = clusterSums[found->second];
        cluster.normal += vertex.normal;
        cluster.uv += vertex.uv;
        ++cluster.count;
        vertexCluster[i] = found->second;
        vertexCell[i] = cell;
    }

    Mesh result;
    result.vertices.reserve(clusterSums.size());
    for (std::size_t c = 0; c < clusterSums.size(); ++c) {
        const Sum& cluster = clusterSums[c];
        const Sum& cell = cellSums[clusterCell[c]];
        const float length = glm::length(cluster.normal);
        result.vertices.push_back({cell.position / float(cell.count),
                                   length > 0.0f ? cluster.normal / length : glm::vec3(0, 1, 0),
                                   cluster.uv / float(cluster.count)});
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        // Two corners in one cell: the triangle collapsed to a line or a point.
        if (vertexCell[a] == vertexCell[b] || vertexCell[b] == vertexCell[c] ||
            vertexCell[a] == vertexCell[c])
            continue;
        result.indices.insert(result.indices.end(),
                              {vertexCluster[a], vertexCluster[b], vertexCluster[c]});
    }
    return result;
}

std::vector<Mesh> levelsOfDetail(const Mesh& mesh) {
    std::vector<Mesh> levels{mesh};
    for (int cells = 64; cells >= 4 && levels.back().triangleCount() > kFewestTriangles;
         cells /= 2) {
        Mesh coarser = clusterVertices(mesh, cells);
        if (coarser.triangleCount() == 0) break;
        if (coarser.triangleCount() * 2 > levels.back().triangleCount()) continue;
        levels.push_back(std::move(coarser));
    }
    return levels;
}

}  // namespace matevo
