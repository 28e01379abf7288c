// The lobe table: exact at its nodes (tint included), in range between them, and shaped by the
// family (a texel axis only for a textured-roughness layer).
#include "material/LobeTable.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "material/FgdTableCache.h"

namespace matevo {
namespace {

MaterialInstance mediumMetal(TexturedLayer texturedLayer) {
    MaterialInstance material;
    material.family = {Coat::Clearcoat, Base::Conductor, true, texturedLayer};
    material.baseKappa = {3.1, 2.9, 2.8};
    material.genome[kEta1] = 1.46;
    material.genome[kEta2] = 0.8;
    material.genome[kAlpha1] = 0.6;
    material.genome[kAlpha2] = 0.35;
    material.genome[kDepth] = 0.4;
    for (std::size_t c = kSigmaSR; c <= kSigmaAB; ++c)
        material.genome[c] = 0.2 + 0.1 * double(c % 3);
    material.genome[kG] = 0.7;
    return material;
}

void expectSameLobe(const Lobe& table, const Lobe& exact, const std::string& where) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(table.energy[c], exact.energy[c], 1e-6 + 1e-6 * exact.energy[c]) << where;
    EXPECT_NEAR(table.alpha, exact.alpha, 1e-5) << where;
}

TEST(LobeTable, EqualsTheAddingLoopAtItsNodesForAnyTint) {
    const LobeTableShape shape{9, 5};
    for (TexturedLayer layer : {TexturedLayer::None, TexturedLayer::Top, TexturedLayer::Bottom}) {
        const MaterialInstance material = mediumMetal(layer);
        const LobeTable table = LobeTable::build(material, defaultFgdTables(), shape);
        EXPECT_EQ(table.texelNodes(), layer == TexturedLayer::None ? 1 : shape.texelNodes);
        for (int t = 0; t < table.texelNodes(); ++t) {
            for (int m = 0; m < shape.cosineNodes; ++m) {
                SurfaceTexels texels;
                texels.roughness =
                    table.texelNodes() > 1 ? double(t) / (shape.texelNodes - 1) : 1.0;
                texels.baseColor = {0.9, 0.4 + 0.05 * t, 0.1 + 0.1 * m};
                const double mu = double(m) / (shape.cosineNodes - 1);
                const LobeSet exact =
                    computeLobes(makeLayerStack(material, texels), mu, defaultFgdTables());
                const LobeSet interpolated = table.lobesAt(mu, texels);
                const std::string where = "layer " + std::to_string(int(layer)) + " t " +
                                          std::to_string(t) + " m " + std::to_string(m);
                expectSameLobe(interpolated.coat, exact.coat, where);
                expectSameLobe(interpolated.base, exact.base, where);
            }
        }
    }
}

// Painted metal's alpha1 = 2.5 x texel saturates at texel 0.9999 / 2.5, where the loop has a
// kink; the texel axis puts a node there, so the table follows the loop on both sides of it.
TEST(LobeTable, ASaturatingTexturedRoughnessHasANodeOnItsKink) {
    MaterialInstance material = mediumMetal(TexturedLayer::Top);
    material.family.hasMedium = false;
    material.genome[kAlpha1] = 2.5;
    material.genome[kDepth] = 0.0;
    for (std::size_t c = kSigmaSR; c <= kSigmaAB; ++c) material.genome[c] = 0.0;
    const LobeTable table = LobeTable::build(material, defaultFgdTables());
    const TexelAxis& axis = table.texelAxis();
    const double knee = 0.9999 / 2.5;
    EXPECT_DOUBLE_EQ(axis.texelAt(axis.kneeNode), knee);
    EXPECT_EQ(axis.texelAt(0), 0.0);
    EXPECT_EQ(axis.texelAt(axis.nodes - 1), 1.0);
    EXPECT_DOUBLE_EQ(axis.position(knee), axis.kneeNode);
    double largestAlphaError = 0.0;
    for (double texel = knee - 0.03; texel < knee + 0.03; texel += 0.001) {
        SurfaceTexels texels;
        texels.roughness = texel;
        const LobeSet exact =
            computeLobes(makeLayerStack(material, texels), 0.7, defaultFgdTables());
        const LobeSet interpolated = table.lobesAt(0.7, texels);
        largestAlphaError =
            std::max({largestAlphaError, std::abs(interpolated.base.alpha - exact.base.alpha),
                      std::abs(interpolated.coat.alpha - exact.coat.alpha)});
    }
    // Between two even nodes across the kink the base alpha was off by 0.066.
    EXPECT_LT(largestAlphaError, 2e-3);
    // An even axis when nothing saturates.
    const TexelAxis even(33, 1.0);
    EXPECT_EQ(even.kneeNode, 32);
    EXPECT_DOUBLE_EQ(even.texelAt(8), 0.25);
}

TEST(LobeTable, BetweenNodesStaysBetweenTheNeighbours) {
    const MaterialInstance material = mediumMetal(TexturedLayer::None);
    const LobeTable table = LobeTable::build(material, defaultFgdTables(), {5, 2});
    const SurfaceTexels white;
    const LobeSet below = table.lobesAt(0.5, white), above = table.lobesAt(0.75, white);
    const LobeSet between = table.lobesAt(0.6, white);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(between.coat.energy[c], 0.6 * below.coat.energy[c] + 0.4 * above.coat.energy[c],
                    1e-12);
        EXPECT_GE(between.base.energy[c], std::min(below.base.energy[c], above.base.energy[c]));
        EXPECT_LE(between.base.energy[c], std::max(below.base.energy[c], above.base.energy[c]));
    }
    // Outside [0, 1] the end nodes hold.
    EXPECT_EQ(table.lobesAt(1.5, white).base.energy, table.lobesAt(1.0, white).base.energy);
}

}  // namespace
}  // namespace matevo
