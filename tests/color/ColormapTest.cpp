#include "color/Colormap.h"

#include <gtest/gtest.h>

#include "color/ColorSpaces.h"
#include "color/Srgb.h"
#include "color/ViridisTable.h"

namespace matevo {
namespace {

std::array<float, 3> decoded(const std::array<float, 3>& srgb) {
    return {float(srgbToLinear(srgb[0])), float(srgbToLinear(srgb[1])),
            float(srgbToLinear(srgb[2]))};
}

// The ends of the published viridis table (van der Walt & Smith 2015).
TEST(Colormap, EndsAreThePublishedViridisColours) {
    const auto first = colormapSrgb(0.0);
    const auto last = colormapSrgb(1.0);
    EXPECT_FLOAT_EQ(first[0], 0.267004f);
    EXPECT_FLOAT_EQ(first[1], 0.004874f);
    EXPECT_FLOAT_EQ(first[2], 0.329415f);
    EXPECT_FLOAT_EQ(last[0], 0.993248f);
    EXPECT_FLOAT_EQ(last[1], 0.906157f);
    EXPECT_FLOAT_EQ(last[2], 0.143936f);
    EXPECT_EQ(colormapSrgb(-5.0), first);
    EXPECT_EQ(colormapSrgb(7.0), last);
    EXPECT_EQ(colormapLinear(1.0), decoded(last));
}

// What makes the map perceptually ordered: L* rises strictly along it.
TEST(Colormap, LightnessRisesMonotonically) {
    double previous = -1;
    for (const auto& srgb : kViridisSrgb) {
        const auto linear = decoded(srgb);
        const double lightness = linearSrgbToLab({linear[0], linear[1], linear[2]}).l;
        EXPECT_GT(lightness, previous);
        previous = lightness;
    }
}

TEST(Colormap, DeltaERangeMapsOntoTheTable) {
    const HeatmapSettings settings;  // 0-10
    EXPECT_EQ(heatmapColorLinear(0.0, settings), decoded(kViridisSrgb[0]));
    EXPECT_EQ(heatmapColorLinear(10.0, settings), decoded(kViridisSrgb[255]));
    EXPECT_EQ(heatmapColorLinear(25.0, settings), decoded(kViridisSrgb[255]));
    EXPECT_EQ(heatmapColorLinear(5.0, settings), decoded(kViridisSrgb[128]));
    const HeatmapSettings shifted{2.0, 4.0, 0.5};
    EXPECT_EQ(heatmapColorLinear(1.0, shifted), decoded(kViridisSrgb[0]));
    EXPECT_EQ(heatmapColorLinear(3.0, shifted), decoded(kViridisSrgb[128]));
    const HeatmapSettings threshold{3.0, 3.0, 0.5};
    EXPECT_EQ(heatmapColorLinear(3.0, threshold), decoded(kViridisSrgb[0]));
    EXPECT_EQ(heatmapColorLinear(3.1, threshold), decoded(kViridisSrgb[255]));
}

ErrorMap twoPixelMap() {
    ErrorMap map;
    map.width = 2;
    map.height = 1;
    map.values = {10.0f, 0.0f};
    map.covered = {1, 0};
    return map;
}

TEST(Colormap, HeatmapIsTransparentOutsideCoverage) {
    const Image heatmap = heatmapImage(twoPixelMap(), HeatmapSettings{});
    ASSERT_EQ(heatmap.width, 2);
    const auto top = decoded(kViridisSrgb[255]);
    EXPECT_EQ(heatmap.pixel(0, 0)[0], top[0]);
    EXPECT_EQ(heatmap.pixel(0, 0)[2], top[2]);
    EXPECT_EQ(heatmap.pixel(0, 0)[3], 1.0f);
    EXPECT_EQ(heatmap.pixel(1, 0)[3], 0.0f);
}

TEST(Colormap, OverlayBlendsAtOpacityInsideAndKeepsTheCandidateOutside) {
    Image candidate(2, 1);
    for (float& value : candidate.rgba) value = 0.5f;
    candidate.pixel(1, 0)[3] = 0.0f;  // outside the sphere
    const auto top = decoded(kViridisSrgb[255]);
    for (double opacity : {0.0, 0.25, 1.0}) {
        const Image overlay = overlayHeatmap(candidate, twoPixelMap(), {0, 10, opacity});
        ASSERT_EQ(overlay.width, 2);
        for (int c = 0; c < 3; ++c)
            EXPECT_FLOAT_EQ(overlay.pixel(0, 0)[c],
                            float((1 - opacity) * 0.5 + opacity * top[std::size_t(c)]));
        EXPECT_EQ(overlay.pixel(0, 0)[3], 0.5f);
        for (int c = 0; c < 4; ++c) EXPECT_EQ(overlay.pixel(1, 0)[c], candidate.pixel(1, 0)[c]);
    }
    EXPECT_EQ(overlayHeatmap(Image(3, 1), twoPixelMap(), {}).width, 0);
}

}  // namespace
}  // namespace matevo
