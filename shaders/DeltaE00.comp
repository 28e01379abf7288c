#version 450
#extension GL_GOOGLE_include_directive : require
// Per-pixel CIEDE2000 between one reference image and a batch of candidates. Mirrors
// core/color: linear sRGB clamped to [0,1] -> XYZ (D65) -> L*a*b* (white Y = 1) -> CIEDE2000
// (kL = kC = kH = 1). Only pixels covered in both images (alpha >= 0.5, core/color/Coverage.h)
// are compared; the others get deltaE = -1.
layout(local_size_x = 64) in;

// The reference and the candidates may share one buffer (the renderer's): they are addressed
// by image index within their bindings.
layout(std430, binding = 0) readonly buffer Reference { vec4 referencePixels[]; };
layout(std430, binding = 1) readonly buffer Candidates { vec4 candidatePixels[]; };
layout(std430, binding = 2) writeonly buffer DeltaE { float deltaE[]; };

layout(push_constant) uniform Settings {
    uint pixelCount;      // per image
    uint referenceImage;  // index of the reference in binding 0
    uint firstCandidate;  // index of the first candidate in binding 1
} settings;

#include "LinearSrgbToLab.glsl"
#include "Ciede2000.glsl"

void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= settings.pixelCount) return;
    uint index = gl_GlobalInvocationID.y * settings.pixelCount + pixel;
    vec4 reference = referencePixels[settings.referenceImage * settings.pixelCount + pixel];
    uint candidateImage = settings.firstCandidate + gl_GlobalInvocationID.y;
    vec4 candidate = candidatePixels[candidateImage * settings.pixelCount + pixel];
    if (reference.a < 0.5 || candidate.a < 0.5) {
        deltaE[index] = -1.0;
        return;
    }
    deltaE[index] = ciede2000(linearSrgbToLab(reference.rgb), linearSrgbToLab(candidate.rgb));
}
