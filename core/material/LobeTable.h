#pragma once
// The lobes of one material precomputed over the view cosine (and, for a family with a
// textured-roughness layer, over the roughness texel) and interpolated linearly per shading
// point: the adding loop runs a few hundred times per material instead of at every subsample.
// The base-colour tint needs no axis: the base lobe is stored as a TintableLobe, which applies
// it exactly. Both back ends shade from the same table (the GPU uploads data() as-is), so they
// agree; the interpolation error against the loop at every point is measured in
// docs/belcour-decisions.md and bounded by tests/scene.
#include <span>
#include <vector>

#include "material/InterfaceAlbedo.h"
#include "material/LayerStack.h"
#include "material/LayeredLobes.h"
#include "material/MaterialInstance.h"

namespace matevo {

// Uniform nodes over cos_view in [0, 1]; nodes over the roughness texel in [0, 1] (texels are
// clamped) as TexelAxis places them; the defaults are chosen by measurement
// (docs/belcour-decisions.md).
struct LobeTableShape {
    int cosineNodes = 32;
    int texelNodes = 33;  // used only by a family with a textured-roughness layer
};

// The texel axis: `nodes` nodes over [0, 1], even on either side of node `kneeNode`, which sits
// on the texel `knee` where the textured roughness saturates (saturatingRoughnessTexel). The
// loop has a kink there (the variance's pole is clamped); on a node the interpolation follows
// it, between two nodes it cut the corner by up to ΔE00 2.5 on painted metal. Without a knee
// inside (0, 1) the knee is 1 on the last node: even nodes.
struct TexelAxis {
    int nodes = 1;
    int kneeNode = 0;
    double knee = 1.0;

    TexelAxis() = default;
    TexelAxis(int nodeCount, double saturatingTexel);
    double texelAt(int node) const;
    // The continuous node coordinate of a texel (clamped to [0, 1]), in [0, nodes - 1].
    double position(double texel) const;
};

class LobeTable {
public:
    // One entry, as floats: coat energy RGB, coat alpha, base throughput RGB, c(base variance),
    // base round trip RGB, c(base variance + round-trip variance), with c(v) = v / (1 + v)
    // (three vec4 on the GPU).
    static constexpr int kFloatsPerEntry = 12;

    static LobeTable build(const MaterialInstance& material, const InterfaceAlbedo& albedo,
                           const LobeTableShape& shape = {});

    // The lobes at one shading point (LobeSet::transmittance is not tabulated: zero).
    LobeSet lobesAt(double cosView, const SurfaceTexels& texels) const;

    int cosineNodes() const { return cosineNodes_; }
    // One node when the family has no textured layer.
    const TexelAxis& texelAxis() const { return texelAxis_; }
    int texelNodes() const { return texelAxis_.nodes; }
    // Entry (texel node t, cosine node m) starts at (t * cosineNodes() + m) * kFloatsPerEntry.
    std::span<const float> data() const { return entries_; }

private:
    int cosineNodes_ = 2;
    TexelAxis texelAxis_;
    std::vector<float> entries_;
};

}  // namespace matevo
