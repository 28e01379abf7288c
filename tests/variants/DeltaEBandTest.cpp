#include "fitness/DeltaEBand.h"

#include <gtest/gtest.h>

#include <limits>

namespace matevo {
namespace {

TEST(DeltaEBand, ViolationIsTheDistanceToTheNearerEdge) {
    const DeltaEBand band{2, 5};
    EXPECT_EQ(band.violation(0.5), 1.5);
    EXPECT_EQ(band.violation(2), 0);
    EXPECT_EQ(band.violation(3.3), 0);
    EXPECT_EQ(band.violation(5), 0);
    EXPECT_EQ(band.violation(7.5), 2.5);
    EXPECT_TRUE(band.contains(2));
    EXPECT_TRUE(band.contains(5));
    EXPECT_FALSE(band.contains(5.0001));
}

TEST(DeltaEBand, ZeroBandScoresThePlainDeltaE) {
    const DeltaEBand plain{0, 0};
    EXPECT_EQ(plain.violation(3.25), 3.25);
}

TEST(DeltaEBand, InsetNeverCrossesTheCentre) {
    EXPECT_EQ((DeltaEBand{2, 5}.inset(0.5)), (DeltaEBand{2.5, 4.5}));
    EXPECT_EQ((DeltaEBand{2, 3}.inset(1)), (DeltaEBand{2.5, 2.5}));
}

TEST(DeltaEBand, ValidationNamesTheProblem) {
    EXPECT_FALSE(validateBand({2, 5}));
    EXPECT_FALSE(validateBand({1, 1}));
    EXPECT_TRUE(validateBand({5, 2}));
    EXPECT_TRUE(validateBand({-1, 2}));
    EXPECT_TRUE(validateBand({0, std::numeric_limits<double>::infinity()}));
    EXPECT_TRUE(validateBand({std::numeric_limits<double>::quiet_NaN(), 2}));
}

TEST(DeltaEBand, PaperBandsAreThePapersReadings) {
    EXPECT_EQ(kPaperBands[0].band, (DeltaEBand{0, 1}));
    EXPECT_EQ(kPaperBands[1].band, (DeltaEBand{1, 2}));
    EXPECT_EQ(kPaperBands[2].band, (DeltaEBand{2, 10}));
    EXPECT_EQ(describe(DeltaEBand{2, 5}), "2-5");
}

}  // namespace
}  // namespace matevo
