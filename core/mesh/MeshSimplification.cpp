#include "mesh/MeshSimplification.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace matevo {
namespace {

// Normals closer than this (cos 60 degrees) share one output vertex in a cell.
constexpr float kSameSurfaceCosine = 0.5f;

struct Cell {
    glm::dvec3 positionSum{0.0};
    int vertices = 0;
    std::vector<std::uint32_t> groups;  // into the groups below
};

// The vertices of one cell on one side of its creases: one output vertex.
struct Group {
    std::uint32_t cell = 0;
    glm::vec3 firstNormal{0.0f};
    glm::dvec3 normalSum{0.0};
    glm::dvec2 uvSum{0.0};
    int vertices = 0;
};

}  // namespace

Mesh simplifyByVertexClustering(const Mesh& mesh, int cellsPerSide) {
    if (mesh.vertices.empty()) return mesh;
    glm::vec3 low = mesh.vertices.front().position, high = low;
    for (const MeshVertex& vertex : mesh.vertices) {
        low = glm::min(low, vertex.position);
        high = glm::max(high, vertex.position);
    }
    const float extent = std::max({high.x - low.x, high.y - low.y, high.z - low.z});
    const int cells = std::max(cellsPerSide, 1);
    if (!(extent > 0.0f)) return mesh;
    const float cellSize = extent / float(cells);
    const auto cellKey = [&](const glm::vec3& position) {
        const glm::ivec3 at = glm::clamp(glm::ivec3(glm::floor((position - low) / cellSize)),
                                         glm::ivec3(0), glm::ivec3(cells - 1));
        return (std::uint64_t(at.z) * std::uint64_t(cells) + std::uint64_t(at.y)) *
                   std::uint64_t(cells) +
               std::uint64_t(at.x);
    };

    std::unordered_map<std::uint64_t, std::uint32_t> cellOfKey;
    std::vector<Cell> cellList;
    std::vector<Group> groups;
    std::vector<std::uint32_t> groupOfVertex(mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const MeshVertex& vertex = mesh.vertices[v];
        const auto [found, added] =
            cellOfKey.try_emplace(cellKey(vertex.position), std::uint32_t(cellList.size()));
        if (added) cellList.emplace_back();
        Cell& cell = cellList[found->second];
        cell.positionSum += glm::dvec3(vertex.position);
        ++cell.vertices;
        const auto same =
            std::find_if(cell.groups.begin(), cell.groups.end(), [&](std::uint32_t g) {
                return glm::dot(groups[g].firstNormal, vertex.normal) > kSameSurfaceCosine;
            });
        std::uint32_t group = 0;
        if (same != cell.groups.end()) {
            group = *same;
        } else {
            group = std::uint32_t(groups.size());
            groups.push_back({found->second, vertex.normal, glm::dvec3(0.0), glm::dvec2(0.0), 0});
            cell.groups.push_back(group);
        }
        groups[group].normalSum += glm::dvec3(vertex.normal);
        groups[group].uvSum += glm::dvec2(vertex.uv);
        ++groups[group].vertices;
        groupOfVertex[v] = group;
    }

    Mesh simplified;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const std::uint32_t corners[3] = {groupOfVertex[mesh.indices[i]],
                                          groupOfVertex[mesh.indices[i + 1]],
                                          groupOfVertex[mesh.indices[i + 2]]};
        const std::uint32_t a = groups[corners[0]].cell, b = groups[corners[1]].cell,
                            c = groups[corners[2]].cell;
        if (a == b || b == c || a == c) continue;  // collapsed to a line or a point
        simplified.indices.insert(simplified.indices.end(), corners, corners + 3);
    }
    if (simplified.indices.empty()) return mesh;
    simplified.vertices.reserve(groups.size());
    for (const Group& group : groups) {
        const Cell& cell = cellList[group.cell];
        MeshVertex vertex;
        vertex.position = glm::vec3(cell.positionSum / double(cell.vertices));
        const double length = glm::length(group.normalSum);
        vertex.normal = length > 0.0 ? glm::vec3(group.normalSum / length) : group.firstNormal;
        vertex.uv = glm::vec2(group.uvSum / double(group.vertices));
        simplified.vertices.push_back(vertex);
    }
    return simplified;
}

}  // namespace matevo
