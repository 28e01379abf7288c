#include "variants/VariantArchive.h"

#include <gtest/gtest.h>

#include "genome/Genome.h"

namespace matevo {
namespace {

// A flat grey patch of linear value v: distances between patches are plain CIEDE2000 between
// greys, i.e. their L* difference over the lightness weighting.
LabImage greyPatch(float value) {
    Image image(4, 4);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        float* p = &image.rgba[4 * i];
        p[0] = p[1] = p[2] = value;
        p[3] = 1;
    }
    return toLabImage(image);
}

Genome genomeNumber(double n) { return Genome{{1.2, 0.8, 0.03, n}}; }

bool offer(VariantArchive& archive, const Genome& genome, const LabImage& lab) {
    return archive.offer(genome, {lab}, {3.0}, archive.distancesTo({lab}));
}

void expectSpacing(const VariantArchive& archive) {
    for (std::size_t i = 0; i < archive.size(); ++i)
        for (std::size_t j = i + 1; j < archive.size(); ++j) {
            EXPECT_GE(archive.distance(i, j), archive.minApart()) << i << ", " << j;
            EXPECT_NEAR(archive.distance(i, j),
                        meanDeltaE00(archive.members()[i].labs[0], archive.members()[j].labs[0]),
                        1e-12);
            EXPECT_FALSE(archive.members()[i].genome == archive.members()[j].genome);
        }
}

TEST(VariantArchive, KeepsEveryPairAtLeastMinApartAndNoDuplicates) {
    VariantArchive archive(2.0);
    // 60 greys 0.5 % apart in linear value, in a scattered order: many fall inside one
    // another's niche.
    for (int k = 0; k < 60; ++k) {
        const int i = (k * 7) % 60;
        offer(archive, genomeNumber(0.1 + 0.01 * i), greyPatch(0.2f + 0.005f * float(i)));
    }
    // The same genome again changes nothing.
    EXPECT_FALSE(offer(archive, genomeNumber(0.1), greyPatch(0.9f)));
    EXPECT_GT(archive.size(), 3u);
    expectSpacing(archive);
}

TEST(VariantArchive, ANewcomerWithMoreRoomTakesTheNiche) {
    VariantArchive archive(2.0);
    const LabImage a = greyPatch(0.20f), b = greyPatch(0.40f);
    ASSERT_TRUE(offer(archive, genomeNumber(0.1), a));
    ASSERT_TRUE(offer(archive, genomeNumber(0.2), b));
    const double gap = meanDeltaE00(a, b);
    ASSERT_GE(gap, 2.0);
    // Close to a (inside its niche) but farther from b than a is: replaces a.
    const LabImage darker = greyPatch(0.19f);
    ASSERT_LT(meanDeltaE00(darker, a), 2.0);
    EXPECT_TRUE(offer(archive, genomeNumber(0.3), darker));
    ASSERT_EQ(archive.size(), 2u);
    EXPECT_EQ(archive.members()[0].genome, genomeNumber(0.3));
    // Close to a's replacement and nearer to b: refused.
    EXPECT_FALSE(offer(archive, genomeNumber(0.4), greyPatch(0.195f)));
    expectSpacing(archive);
}

TEST(VariantArchive, PinnedMembersAreNeverReplaced) {
    VariantArchive archive(2.0);
    archive.pin(genomeNumber(0.1), {greyPatch(0.20f)}, {3.0});
    offer(archive, genomeNumber(0.2), greyPatch(0.40f));
    EXPECT_FALSE(offer(archive, genomeNumber(0.3), greyPatch(0.19f)));
    EXPECT_EQ(archive.members()[0].genome, genomeNumber(0.1));
    EXPECT_TRUE(archive.members()[0].pinned);
}

TEST(VariantArchive, IdsGrowAndReplacedMembersLeave) {
    VariantArchive archive(2.0);
    offer(archive, genomeNumber(0.1), greyPatch(0.20f));
    offer(archive, genomeNumber(0.2), greyPatch(0.40f));
    const std::uint64_t replacedId = archive.members()[0].id;
    ASSERT_TRUE(offer(archive, genomeNumber(0.3), greyPatch(0.19f)));
    EXPECT_FALSE(archive.holds(replacedId));
    EXPECT_TRUE(archive.holds(archive.members()[0].id));
    EXPECT_EQ(archive.members()[0].id, archive.lastId());
    EXPECT_GT(archive.members()[0].id, archive.members()[1].id);
}

// Two lightings: the patches stand apart under the first and are twins under the second, as
// two variants may look distinct under the paper's light and alike in the studio.
TEST(VariantArchive, UnderSeveralLightingsApartMeansApartUnderEveryOne) {
    VariantArchive archive(2.0);
    const LabsPerLighting first{greyPatch(0.20f), greyPatch(0.30f)};
    const LabsPerLighting second{greyPatch(0.40f), greyPatch(0.301f)};
    ASSERT_GE(meanDeltaE00(first[0], second[0]), 2.0);
    ASSERT_LT(meanDeltaE00(first[1], second[1]), 2.0);
    ASSERT_TRUE(archive.offer(genomeNumber(0.1), first, {3.0, 3.0}, archive.distancesTo(first)));
    const std::vector<double> distances = archive.distancesTo(second);
    EXPECT_NEAR(distances[0], meanDeltaE00(first[1], second[1]), 1e-12);
    archive.offer(genomeNumber(0.2), second, {3.0, 3.0}, distances);
    EXPECT_EQ(archive.size(), 1u);
    // Apart under both: joins.
    const LabsPerLighting third{greyPatch(0.40f), greyPatch(0.50f)};
    EXPECT_TRUE(archive.offer(genomeNumber(0.3), third, {3.0, 3.0}, archive.distancesTo(third)));
    EXPECT_EQ(archive.size(), 2u);
}

}  // namespace
}  // namespace matevo
