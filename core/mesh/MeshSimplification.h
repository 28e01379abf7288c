#pragma once
// A coarse version of a mesh for the scene view's previews while the camera moves (the editor's
// Scene window): at a quarter of the window's resolution a shader ball is a few dozen pixels
// wide, so its 24,416 triangles are mostly smaller than a pixel, and the visibility pass pays
// per triangle. Vertex clustering (Rossignac and Borrel 1993): the bounding box is cut into a
// grid of cubic cells, every vertex in a cell moves to the mean of the cell's vertices, and
// triangles left with fewer than three distinct cells vanish. Within a cell, vertices whose
// normals differ by more than 60 degrees keep separate normals (on the same position), so
// creases stay sharp without opening cracks. Orientation is kept; texture coordinates are
// averaged like the normals.
#include "mesh/Mesh.h"

namespace matevo {

// `cellsPerSide` cells along the longest side of the bounding box (at least 1). A mesh that
// would lose every triangle comes back unchanged.
Mesh simplifyByVertexClustering(const Mesh& mesh, int cellsPerSide);

}  // namespace matevo
