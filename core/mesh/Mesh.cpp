#include "mesh/Mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace matevo {

void computeVertexNormals(Mesh& mesh) {
    std::vector<glm::vec3> sums(mesh.vertices.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        // The cross product's length is twice the triangle's area: larger faces weigh more.
        const glm::vec3 faceNormal =
            glm::cross(mesh.vertices[b].position - mesh.vertices[a].position,
                       mesh.vertices[c].position - mesh.vertices[a].position);
        sums[a] += faceNormal;
        sums[b] += faceNormal;
        sums[c] += faceNormal;
    }
    for (std::size_t v = 0; v < sums.size(); ++v) {
        const float length = glm::length(sums[v]);
        mesh.vertices[v].normal = length > 0.0f ? sums[v] / length : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

void fitToUnitSphere(Mesh& mesh) {
    if (mesh.vertices.empty()) return;
    glm::vec3 low(std::numeric_limits<float>::max());
    glm::vec3 high(std::numeric_limits<float>::lowest());
    for (const MeshVertex& vertex : mesh.vertices) {
        low = glm::min(low, vertex.position);
        high = glm::max(high, vertex.position);
    }
    const glm::vec3 centre = 0.5f * (low + high);
    float radius = 0.0f;
    for (const MeshVertex& vertex : mesh.vertices)
        radius = std::max(radius, glm::length(vertex.position - centre));
    const float scale = radius > 0.0f ? 1.0f / radius : 1.0f;
    for (MeshVertex& vertex : mesh.vertices) vertex.position = (vertex.position - centre) * scale;
}

Status validateMesh(const Mesh& mesh, const std::string& source) {
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
        return badInput(source + ": no triangles to draw");
    for (std::uint32_t index : mesh.indices)
        if (index >= mesh.vertices.size())
            return badInput(source + ": vertex index " + std::to_string(index) + " out of range (" +
                            std::to_string(mesh.vertices.size()) + " vertices)");
    for (const MeshVertex& vertex : mesh.vertices)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(vertex.position[c]) || !std::isfinite(vertex.normal[c]))
                return badInput(source + ": a vertex position or normal is not a finite number");
    return Ok{};
}

}  // namespace matevo
