#include "material/LobeTable.h"

#include <algorithm>
#include <array>

namespace matevo {

namespace {

// Position of x in [0, 1] on an axis of `count` uniform nodes: lower node and blend weight.
struct AxisPosition {
    int node = 0;
    double weight = 0.0;
};

AxisPosition locate(double x, int count) {
    if (count < 2) return {};
    const double position = std::clamp(x, 0.0, 1.0) * (count - 1);
    const int node = std::min(int(position), count - 2);
    return {node, position - node};
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

LobeTable LobeTable::build(const MaterialInstance& material, const InterfaceAlbedo& albedo,
                           const LobeTableShape& shape) {
    LobeTable table;
    table.cosineNodes_ = std::max(shape.cosineNodes, 2);
    table.texelNodes_ =
        material.family.texturedLayer == TexturedLayer::None ? 1 : std::max(shape.texelNodes, 2);
    const int cosineNodes = table.cosineNodes_;
    table.entries_.resize(std::size_t(table.texelNodes_) * cosineNodes * kFloatsPerEntry);
    for (int t = 0; t < table.texelNodes_; ++t) {
        SurfaceTexels texels;
        if (table.texelNodes_ > 1) texels.roughness = double(t) / (table.texelNodes_ - 1);
        const LayerStack stack = makeLayerStack(material, texels);
        for (int m = 0; m < cosineNodes; ++m)
            store(&table.entries_[std::size_t(t * cosineNodes + m) * kFloatsPerEntry],
                  computeUntintedLobes(stack, double(m) / (cosineNodes - 1), albedo));
    }
    return table;
}

LobeSet LobeTable::lobesAt(double cosView, const SurfaceTexels& texels) const {
    const AxisPosition cosine = locate(cosView, cosineNodes_);
    const AxisPosition texel = locate(texels.roughness, texelNodes_);
    std::array<double, kFloatsPerEntry> v{};
    for (int dt = 0; dt < std::min(texelNodes_, 2); ++dt) {
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
