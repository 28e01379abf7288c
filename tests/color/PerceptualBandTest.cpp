#include "color/PerceptualBand.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "color/ColorSpaces.h"
#include "color/Srgb.h"

namespace matevo {
namespace {

using Band = PerceptualBand;

// Each band includes its upper edge; the next representable value above belongs to the next.
TEST(PerceptualBand, EdgesBelongToTheLowerBand) {
    const struct {
        double edge;
        Band atEdge, above;
    } edges[] = {{1.0, Band::kNotPerceptible, Band::kCloseObservation},
                 {2.0, Band::kCloseObservation, Band::kAtAGlance},
                 {10.0, Band::kAtAGlance, Band::kMoreSimilarThanOpposite},
                 {49.0, Band::kMoreSimilarThanOpposite, Band::kOpposite}};
    for (const auto& e : edges) {
        EXPECT_EQ(classifyDeltaE(e.edge), e.atEdge) << e.edge;
        EXPECT_EQ(classifyDeltaE(std::nextafter(e.edge, 100.0)), e.above) << e.edge;
        EXPECT_EQ(bandUpperEdge(e.atEdge), e.edge);
    }
}

TEST(PerceptualBand, InteriorAndOutOfRangeValues) {
    EXPECT_EQ(classifyDeltaE(0.0), Band::kNotPerceptible);
    EXPECT_EQ(classifyDeltaE(-3.0), Band::kNotPerceptible);
    EXPECT_EQ(classifyDeltaE(1.5), Band::kCloseObservation);
    EXPECT_EQ(classifyDeltaE(5.0), Band::kAtAGlance);
    EXPECT_EQ(classifyDeltaE(30.0), Band::kMoreSimilarThanOpposite);
    EXPECT_EQ(classifyDeltaE(100.0), Band::kOpposite);
    EXPECT_EQ(classifyDeltaE(std::numeric_limits<double>::infinity()), Band::kOpposite);
    EXPECT_EQ(classifyDeltaE(std::numeric_limits<double>::quiet_NaN()), Band::kOpposite);
    EXPECT_TRUE(std::isinf(bandUpperEdge(Band::kOpposite)));
}

TEST(PerceptualBand, LegendTextsAndColoursAreDistinctAndOrdered) {
    std::set<std::string> labels, descriptions;
    double previousLightness = -1;
    for (Band band : kPerceptualBands) {
        labels.emplace(bandRangeLabel(band));
        descriptions.emplace(bandDescription(band));
        const auto srgb = bandColorSrgb(band);
        const double lightness =
            linearSrgbToLab({srgbToLinear(srgb[0]), srgbToLinear(srgb[1]), srgbToLinear(srgb[2])})
                .l;
        EXPECT_GT(lightness, previousLightness + 10.0) << bandRangeLabel(band);
        previousLightness = lightness;
    }
    EXPECT_EQ(labels.size(), std::size_t(kPerceptualBandCount));
    EXPECT_EQ(descriptions.size(), std::size_t(kPerceptualBandCount));
    EXPECT_EQ(bandRangeLabel(Band::kNotPerceptible), "<= 1");
    EXPECT_EQ(bandRangeLabel(Band::kOpposite), "> 49");
}

}  // namespace
}  // namespace matevo
