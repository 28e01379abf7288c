#pragma once
// A triangle mesh as the raster renderer draws it: interleaved vertices (position, unit normal,
// texture coordinate) and a triangle list of indices. Loaders and generators all produce this.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "common/Result.h"

namespace matevo {

struct MeshVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
};

struct Mesh {
    std::vector<MeshVertex> vertices;
    std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise seen from outside

    std::size_t triangleCount() const { return indices.size() / 3; }
};

// Area-weighted vertex normals from the triangles (for files that carry none).
void computeVertexNormals(Mesh& mesh);

// Moves the bounding box's centre to the origin and scales the mesh so that every vertex lies
// within distance 1 of it: instances of any mesh then fit the same layout cell.
void fitToUnitSphere(Mesh& mesh);

// A mesh the renderer can draw: at least one triangle, indices in range, finite positions.
// `source` names the file in the message.
Status validateMesh(const Mesh& mesh, const std::string& source);

}  // namespace matevo
