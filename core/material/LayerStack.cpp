#include "material/LayerStack.h"

#include <algorithm>

#include "material/RoughnessMap.h"

namespace matevo {

namespace {

Rgb toRgb(const std::array<double, 3>& values) { return {values[0], values[1], values[2]}; }

// A non-positive IOR from an out-of-range genome would divide by zero in the relative index.
constexpr double kMinimumEta = 1e-3;

}  // namespace

LayerStack makeLayerStack(const MaterialInstance& material, const SurfaceTexels& texels) {
    const Genome& genome = material.genome;
    const MaterialFamily& family = material.family;
    const double topWeight = family.texturedLayer == TexturedLayer::Top ? texels.roughness : 1.0;
    const double bottomWeight =
        family.texturedLayer == TexturedLayer::Bottom ? texels.roughness : 1.0;

    LayerStack stack;
    stack.coat.eta = Rgb(std::max(genome.eta1(), kMinimumEta));
    stack.coat.alpha = std::max(0.0, genome.alpha1() * topWeight);
    stack.base.eta = Rgb(std::max(genome.eta2(), kMinimumEta));
    stack.base.alpha = std::max(0.0, genome.alpha2() * bottomWeight);
    stack.base.tint = toRgb(texels.baseColor);
    if (family.base == Base::Conductor) stack.base.kappa = toRgb(material.baseKappa);

    const MediumLayer medium{genome.depth(), toRgb(genome.sigmaS()), toRgb(genome.sigmaA()),
                             genome.g()};
    const Rgb extinction = (medium.sigmaS + medium.sigmaA) * medium.depth;
    if (family.hasMedium && medium.depth > 0.0 &&
        std::max({extinction.r, extinction.g, extinction.b}) > 0.0)
        stack.medium = medium;
    return stack;
}

double saturatingRoughnessTexel(const MaterialInstance& material) {
    const TexturedLayer textured = material.family.texturedLayer;
    if (textured == TexturedLayer::None) return 1.0;
    const double weight =
        textured == TexturedLayer::Top ? material.genome.alpha1() : material.genome.alpha2();
    return weight > kMaximumRoughness ? kMaximumRoughness / weight : 1.0;
}

}  // namespace matevo
