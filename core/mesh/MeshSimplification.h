#pragma once
// Coarser versions of a mesh for instances seen small (levels of detail). A triangle much
// smaller than a pixel costs a software rasteriser as much as a large one (lavapipe shades at
// least a 2 x 2 quad per triangle), so a crowd of 100 finely tessellated meshes is bound by
// triangles, not pixels; a far instance drawn from a level with a few pixels per triangle looks
// the same.
//
// Vertex clustering: the mesh's bounding box is cut into cells; the vertices in one cell
// merge into one position (their mean), triangles with two corners in one cell vanish. Normals
// and texture coordinates are merged only among vertices that also agree on the normal's
// dominant direction and the texture's quadrant, so hard edges and UV seams survive (positions
// are shared, so no cracks open).
#include <vector>

#include "mesh/Mesh.h"

namespace matevo {

Mesh clusterVertices(const Mesh& mesh, int cellsPerAxis);

// The mesh, then coarser levels (each with fewer than half the triangles of the one before)
// down to a few hundred triangles.
std::vector<Mesh> levelsOfDetail(const Mesh& mesh);

}  // namespace matevo
