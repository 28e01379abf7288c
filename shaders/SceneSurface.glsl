// What the scene's surface pass stores per pixel for its shading pass (one RGBA32UI texel):
// texture coordinates (float bits), the unit normal octahedron-encoded in two 16-bit snorms,
// and the material index plus one (0: background, nothing drawn).
// Octahedral encoding: Meyer et al. 2010, "On Floating-Point Normal Vectors".

vec2 signNotZero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

uint encodeNormal(vec3 normal) {
    vec2 folded = normal.xy / (abs(normal.x) + abs(normal.y) + abs(normal.z));
    if (normal.z < 0.0) folded = (1.0 - abs(folded.yx)) * signNotZero(folded);
    return packSnorm2x16(folded);
}

vec3 decodeNormal(uint encoded) {
    vec2 folded = unpackSnorm2x16(encoded);
    vec3 normal = vec3(folded, 1.0 - abs(folded.x) - abs(folded.y));
    if (normal.z < 0.0) normal.xy = (1.0 - abs(normal.yx)) * signNotZero(normal.xy);
    return normalize(normal);
}
