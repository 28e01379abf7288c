#version 450
#extension GL_GOOGLE_include_directive : require
// The paper's test scene on the GPU, one invocation per pixel and material: the same camera,
// 2 x 2 subsamples, coverage alpha, sphere UV mapping, textures and shading as the CPU
// reference (core/scene/SphereRenderer.cpp). Workgroups along y are materials, so each
// workgroup runs one layer stack and the loop over slots does not diverge.
layout(local_size_x = 64) in;

struct Material {
    vec4 coatEta;    // xyz absolute IOR of the coat, w alpha1
    vec4 baseEta;    // xyz absolute IOR of the base, w alpha2
    vec4 baseKappa;  // xyz extinction of a conductor base, w textured layer (0, 1 top, 2 bottom)
    vec4 sigmaS;     // xyz scattering of the medium, w depth (0: no medium slot)
    vec4 sigmaA;     // xyz absorption of the medium, w Henyey-Greenstein g
};

layout(std430, binding = 0) readonly buffer Materials { Material materials[]; };
layout(std430, binding = 1) writeonly buffer Renders { vec4 renderPixels[]; };
layout(binding = 2) uniform sampler3D fgdTable;
layout(binding = 3) uniform sampler3D tirTable;
layout(binding = 4) uniform sampler2D roughnessTexture;  // 1x1 white when absent
layout(binding = 5) uniform sampler2D baseColorTexture;  // 1x1 white when absent

layout(std430, binding = 6) readonly buffer Scene {
    vec4 cameraPosition;       // w image size in pixels
    vec4 cameraForward;        // w tan(fov / 2)
    vec4 cameraRight;
    vec4 cameraUp;
    vec4 toLight;
    vec4 lightRadiance;
    vec4 environmentRadiance;
    vec4 tableAxes[4];         // mu, alpha, eta, kappa: (count, min, max, unused)
} scene;

#include "BelcourTables.glsl"

TableAxis tableMu;
TableAxis tableAlpha;
TableAxis tableEta;
TableAxis tableKappa;

#include "BelcourBsdf.glsl"

const int kSubsamplesPerAxis = 2;

vec3 shade(Material material, vec3 normal, vec3 toViewer) {
    vec2 uv = vec2(0.5 + atan(normal.x, normal.z) / (2.0 * kPi),
                   acos(clamp(normal.y, -1.0, 1.0)) / kPi);
    float roughnessTexel = texture(roughnessTexture, uv).r;
    vec3 baseColor = texture(baseColorTexture, uv).rgb;
    float texturedLayer = material.baseKappa.w;

    InterfaceLayer coat = InterfaceLayer(material.coatEta.xyz, vec3(0.0),
        max(0.0, material.coatEta.w * (texturedLayer == 1.0 ? roughnessTexel : 1.0)), vec3(1.0));
    InterfaceLayer base = InterfaceLayer(material.baseEta.xyz, material.baseKappa.xyz,
        max(0.0, material.baseEta.w * (texturedLayer == 2.0 ? roughnessTexel : 1.0)), baseColor);
    MediumLayer medium = MediumLayer(material.sigmaS.w, material.sigmaS.xyz, material.sigmaA.xyz,
                                     material.sigmaA.w);

    float cosView = max(dot(normal, toViewer), 0.0);
    LobeSet lobes = computeLobes(coat, material.sigmaS.w > 0.0, medium, base, cosView);
    vec3 toLight = scene.toLight.xyz;
    float cosLight = dot(normal, toLight);
    float cosHalf = dot(normal, normalize(toViewer + toLight));
    vec3 reflected = evaluateBsdf(lobes, cosView, cosLight, cosHalf) * scene.lightRadiance.rgb *
                     max(cosLight, 0.0);
    return reflected + environmentReflectance(lobes) * scene.environmentRadiance.rgb;
}

void main() {
    int size = int(scene.cameraPosition.w);
    uint pixelCount = uint(size * size);
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= pixelCount) return;
    tableMu = TableAxis(scene.tableAxes[0].x, scene.tableAxes[0].y, scene.tableAxes[0].z);
    tableAlpha = TableAxis(scene.tableAxes[1].x, scene.tableAxes[1].y, scene.tableAxes[1].z);
    tableEta = TableAxis(scene.tableAxes[2].x, scene.tableAxes[2].y, scene.tableAxes[2].z);
    tableKappa = TableAxis(scene.tableAxes[3].x, scene.tableAxes[3].y, scene.tableAxes[3].z);

    Material material = materials[gl_GlobalInvocationID.y];
    vec3 origin = scene.cameraPosition.xyz;
    float tanHalfFov = scene.cameraForward.w;
    int x = int(pixel % uint(size));
    int y = int(pixel / uint(size));

    vec3 sum = vec3(0.0);
    int hits = 0;
    for (int sy = 0; sy < kSubsamplesPerAxis; ++sy) {
        for (int sx = 0; sx < kSubsamplesPerAxis; ++sx) {
            float ndcX = 2.0 * (float(x) + (float(sx) + 0.5) / kSubsamplesPerAxis) / size - 1.0;
            float ndcY = 1.0 - 2.0 * (float(y) + (float(sy) + 0.5) / kSubsamplesPerAxis) / size;
            vec3 direction = normalize(scene.cameraForward.xyz +
                                       ndcX * tanHalfFov * scene.cameraRight.xyz +
                                       ndcY * tanHalfFov * scene.cameraUp.xyz);
            float b = dot(origin, direction);
            float discriminant = b * b - (dot(origin, origin) - 1.0);
            if (discriminant < 0.0) continue;
            float distance = -b - sqrt(discriminant);
            if (distance <= 0.0) continue;
            vec3 normal = normalize(origin + distance * direction);
            sum += shade(material, normal, -direction);
            ++hits;
        }
    }
    uint index = gl_GlobalInvocationID.y * pixelCount + pixel;
    renderPixels[index] = hits == 0 ? vec4(0.0)
                                    : vec4(sum / float(hits),
                                           float(hits) / float(kSubsamplesPerAxis * kSubsamplesPerAxis));
}
