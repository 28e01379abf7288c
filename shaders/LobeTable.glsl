// A material's lobes from its LobeTable (core/material/LobeTable.h), interpolated as
// LobeTable::lobesAt does; shared by the sphere compute shader and the scene's raster shaders.
// The including shader declares, before including this file and BelcourBsdf.glsl:
//   layout(constant_id = N) const bool kTextured = ...;  // false: every roughness texel is 1
//   layout(binding = N) uniform samplerBuffer lobeEntries;
//   layout(binding = M) uniform usamplerBuffer materialRecords;
// texel buffers, not storage buffers: llvmpipe fetches texels for all SIMD lanes at once but
// loads a storage buffer one lane and one component at a time (even at an index the same for
// every lane, once some lanes may be inactive).
// A material record is one RGBA32UI texel: first entry, texel nodes | knee node << 16, cosine
// nodes, the knee texel's float bits (Material below). The lobe table has three RGBA32F
// texels per entry: coat energy + alpha, base throughput + c(variance), base round trip +
// c(variance + round-trip variance) with c(v) = v / (1 + v); entry (texel t, cosine m) at
// firstEntry + t * cosineNodes + m.

struct Material {
    uint firstEntry;   // of its lobe table
    uint texelNodes;   // 1: no textured-roughness axis
    uint kneeNode;     // TexelAxis::kneeNode
    uint cosineNodes;
    float knee;        // TexelAxis::knee
};

Material materialAt(uint index) {
    uvec4 record = texelFetch(materialRecords, int(index));
    return Material(record.x, record.y & 0xffffu, record.y >> 16u, record.z,
                    uintBitsToFloat(record.w));
}

// TexelAxis::position: even nodes on either side of the knee node.
float texelPosition(Material material, float texel) {
    float t = clamp(texel, 0.0, 1.0);
    float kneeNode = float(material.kneeNode);
    if (t <= material.knee) return t / material.knee * kneeNode;
    return kneeNode + (t - material.knee) / (1.0 - material.knee) *
                          (float(material.texelNodes - 1u) - kneeNode);
}

struct Entry {
    vec4 coat;
    vec4 base;
    vec4 roundTrip;
};

void accumulate(inout Entry sum, uint entry, float weight) {
    int texel = int(3u * entry);
    sum.coat += weight * texelFetch(lobeEntries, texel);
    sum.base += weight * texelFetch(lobeEntries, texel + 1);
    sum.roundTrip += weight * texelFetch(lobeEntries, texel + 2);
}

float expandVariance(float compressed) { return compressed / max(1.0 - compressed, 1e-7); }

// LobeTable::lobesAt: linear in cos_view, and in the texel when the table has that axis.
LobeSet lobesAt(Material material, float cosView, float texel, vec3 tint) {
    int cosineNodes = int(material.cosineNodes);
    float cosinePosition = clamp(cosView, 0.0, 1.0) * float(cosineNodes - 1);
    int m = min(int(cosinePosition), cosineNodes - 2);
    float wm = cosinePosition - float(m);
    Entry sum = Entry(vec4(0.0), vec4(0.0), vec4(0.0));
    if (kTextured) {
        // Without a texel axis the second texel row is the first one again, with weight 0:
        // one path for both shapes (lavapipe would run both sides of a branch).
        float position = texelPosition(material, texel);
        uint t = min(uint(position), max(material.texelNodes, 2u) - 2u);
        float wt = position - float(t);
        uint texelStride = material.texelNodes > 1u ? uint(cosineNodes) : 0u;
        uint row = material.firstEntry + t * uint(cosineNodes) + uint(m);
        accumulate(sum, row, (1.0 - wt) * (1.0 - wm));
        accumulate(sum, row + 1u, (1.0 - wt) * wm);
        accumulate(sum, row + texelStride, wt * (1.0 - wm));
        accumulate(sum, row + texelStride + 1u, wt * wm);
    } else {
        // A texel of 1 is the last texel row exactly (weight 1, the other row's weight 0):
        // half the fetches. The branch is resolved when the pipeline is specialised.
        uint row = material.firstEntry + (material.texelNodes - 1u) * uint(cosineNodes) + uint(m);
        accumulate(sum, row, 1.0 - wm);
        accumulate(sum, row + 1u, wm);
    }
    float variance = expandVariance(sum.base.a);
    return LobeSet(Lobe(sum.coat.rgb, sum.coat.a),
                   tintedLobe(sum.base.rgb, sum.roundTrip.rgb, variance,
                              expandVariance(sum.roundTrip.a) - variance, tint));
}

