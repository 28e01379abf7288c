#version 450
// The scene's fixed-function visibility pass, fragment stage: each sample the depth test
// keeps holds the identity of its triangle, as the compute pass (SceneRasterize.comp) writes
// it in the low half of its visibility words. The instance's triangles in the mesh's order
// are consecutive identities, and gl_PrimitiveID counts them from 0 in every instance.
layout(location = 0) flat in uint firstSurface;
layout(location = 0) out uint surface;

void main() { surface = firstSurface + uint(gl_PrimitiveID); }
