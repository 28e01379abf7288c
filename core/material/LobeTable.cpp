#include "material/LobeTable.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace matevo {

namespace {

// A point on an axis: lower node and blend weight.
struct AxisPosition {
    int node = 0;
    double weight = 0.0;
};

// Lower node and blend weight at continuous node coordinate `position` on `count` nodes.
AxisPosition nodePosition(double position, int count) {
    if (count < 2) return {};
    const int node = std::min(int(position), count - 2);
    return {node, position - node};
}

// Position of x in [0, 1] on an axis of `count` uniform nodes.
AxisPosition locate(double x, int count) {
    return nodePosition(std::clamp(x, 0.0, 1.0) * (count - 1), count);
}

// Variances grow without bound as a roughness nears 1 (a textured alpha weight > 1 gets there
// inside the texel range), so they are interpolated as v / (1 + v) in [0, 1): close to
// alpha^1.1 and smooth where the variance is not.
double compress(double variance) { return variance / (1.0 + variance); }
double expand(double compressed) { return compressed / std::max(1.0 - compressed, 1e-7); }

void store(float* entry, const UntintedLobes& lobes) {
    const TintableLobe& base = lobes.base;
    const double withRoundTrip = base.variance + base.roundTripVariance;
    const std::array<double, LobeTable::kFloatsPerEntry> values = {
        lobes.coat.energy[0], lobes.coat.energy[1], lobes.coat.energy[2], lobes.coat.alpha,
        base.throughput.r,    base.throughput.g,    base.throughput.b,    compress(base.variance),
        base.roundTrip.r,     base.roundTrip.g,     base.roundTrip.b,     compress(withRoundTrip)};
    std::transform(values.begin(), values.end(), entry, [](double v) { return float(v); });
}

}  // namespace

TexelAxis::TexelAxis(int nodeCount, double saturatingTexel)
    : nodes(nodeCount), kneeNode(nodeCount - 1) {
    if (nodes < 3 || saturatingTexel <= 0.0 || saturatingTexel >= 1.0) return;
    knee = saturatingTexel;
    kneeNode = std::clamp(int(std::lround(knee * (nodes - 1))), 1, nodes - 2);
}

double TexelAxis::texelAt(int node) const {
    if (node <= kneeNode) return kneeNode > 0 ? knee * node / kneeNode : 0.0;
    return knee + (1.0 - knee) * (node - kneeNode) / (nodes - 1 - kneeNode);
}

double TexelAxis::position(double texel) const {
    const double t = std::clamp(texel, 0.0, 1.0);
    if (t <= knee) return t / knee * kneeNode;
    return kneeNode + (t - knee) / (1.0 - knee) * (nodes - 1 - kneeNode);
}

LobeTable LobeTable::build(const MaterialInstance& material, const InterfaceAlbedo& albedo,
                           const LobeTableShape& shape) {
    LobeTable table;
    table.cosineNodes_ = std::max(shape.cosineNodes, 2);
    const int texelNodes =
        material.family.texturedLayer == TexturedLayer::None ? 1 : std::max(shape.texelNodes, 2);
    table.texelAxis_ = TexelAxis(texelNodes, saturatingRoughnessTexel(material));
    const int cosineNodes = table.cosineNodes_;
    table.entries_.resize(std::size_t(texelNodes) * cosineNodes * kFloatsPerEntry);
    for (int t = 0; t < texelNodes; ++t) {
        SurfaceTexels texels;
        if (texelNodes > 1) texels.roughness = table.texelAxis_.texelAt(t);
        const LayerStack stack = makeLayerStack(material, texels);
        for (int m = 0; m < cosineNodes; ++m)
            store(&table.entries_[std::size_t(t * cosineNodes + m) * kFloatsPerEntry],
                  computeUntintedLobes(stack, double(m) / (cosineNodes - 1), albedo));
    }
    return table;
}

LobeSet LobeTable::lobesAt(double cosView, const SurfaceTexels& texels) const {
    const AxisPosition cosine = locate(cosView, cosineNodes_);
    const AxisPosition texel =
        nodePosition(texelAxis_.position(texels.roughness), texelAxis_.nodes);
    std::array<double, kFloatsPerEntry> v{};
    for (int dt = 0; dt < std::min(texelAxis_.nodes, 2); ++dt) {
        for (int dm = 0; dm < 2; ++dm) {
            const double weight = (dt ? texel.weight : 1.0 - texel.weight) *
                                  (dm ? cosine.weight : 1.0 - cosine.weight);
            const float* entry =
                &entries_[std::size_t((texel.node + dt) * cosineNodes_ + cosine.node + dm) *
                          kFloatsPerEntry];
            for (int i = 0; i < kFloatsPerEntry; ++i) v[i] += weight * entry[i];
        }
    }
    const double variance = expand(v[7]);
    const TintableLobe base{
        {v[4], v[5], v[6]}, {v[8], v[9], v[10]}, variance, expand(v[11]) - variance};
    LobeSet lobes;
    lobes.coat = {{v[0], v[1], v[2]}, v[3]};
    lobes.base = base.tinted({texels.baseColor[0], texels.baseColor[1], texels.baseColor[2]});
    return lobes;
}

}  // namespace matevo
