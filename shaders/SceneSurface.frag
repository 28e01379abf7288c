#version 450
#extension GL_GOOGLE_include_directive : require
// The scene view's surface pass, fragment stage: stores what the shading pass needs of the
// nearest surface (SceneSurface.glsl) and nothing else. Shading happens once per covered pixel
// in SceneShade.frag: llvmpipe shades 4x4-pixel blocks, so shading here, where the mesh's
// triangles are a few pixels each, would shade most pixels several times.
#include "SceneSurface.glsl"

layout(location = 0) in vec3 worldNormal;
layout(location = 1) in vec2 texCoord;
layout(location = 2) flat in uint materialIndex;
layout(location = 0) out uvec4 surface;

void main() {
    surface = uvec4(floatBitsToUint(texCoord), encodeNormal(normalize(worldNormal)),
                    materialIndex + 1u);
}
