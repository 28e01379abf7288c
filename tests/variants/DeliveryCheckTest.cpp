// The delivery check (variants/DeliveryCheck.h) on renders whose distances are known: uniform
// grey images whose CIE lightness is the genome's first gene, so that ΔE00 between two of them is
// about the difference of their genes near L* 50. A delivery format that moves one variant out of
// the band on its first conversion (refitted) and another on every conversion (replaced from the
// archive) must still deliver the whole set, in band and apart on both renders.
#include "variants/DeliveryCheck.h"

#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "color/LabImage.h"

namespace matevo {
namespace {

constexpr int kSide = 4;

// Linear grey of CIE lightness L* (L* > 8).
Image greyOfLightness(double lightness) {
    const double y = std::pow((lightness + 16.0) / 116.0, 3.0);
    Image image(kSide, kSide);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c) image.rgba[4 * i + c] = float(y);
        image.rgba[4 * i + 3] = 1.0f;
    }
    return image;
}

Genome genomeOfLightness(double lightness) {
    Genome genome;
    genome[0] = lightness;
    return genome;
}

Result<std::vector<Image>> renderGreys(std::span<const Genome> genomes) {
    std::vector<Image> images;
    for (const Genome& genome : genomes) images.push_back(greyOfLightness(genome[0]));
    return images;
}

TEST(DeliveryCheck, ARefitOrAReplacementKeepsTheDeliveredSetInBandAndApart) {
    VariantRequest request;
    request.count = 3;
    request.band = {2.0, 8.0};
    request.minApart = 2.0;
    const Genome target = genomeOfLightness(50.0);
    const LabImage targetLab = toLabImage(greyOfLightness(50.0));
    VariantArchive archive(request.minApart);
    // Chosen farthest-first from the band's centre: 55, 44.5, 52.5; then 47 is next in line.
    for (double lightness : {52.5, 55.0, 57.5, 47.0, 44.5}) {
        const LabsPerLighting labs{toLabImage(greyOfLightness(lightness))};
        archive.offer(genomeOfLightness(lightness), labs, {meanDeltaE00(targetLab, labs[0])},
                      archive.distancesTo(labs));
    }
    ASSERT_EQ(archive.size(), 5u);
    auto chosen = chooseVariantSet(archive, request, target, RenderGenomes(renderGreys));
    ASSERT_TRUE(chosen.ok());
    ASSERT_EQ(chosen->variants.size(), 3u);

    // 55 converts to 50.5 (out of the band) the first time and right when refitted; 52.5 converts
    // to 50.5 every time.
    std::map<std::pair<double, int>, int> conversions;
    DeliveryFormat format{
        "grey",
        [&](std::span<const Genome> genomes, int attempt) -> Result<std::vector<Image>> {
            std::vector<Image> images;
            for (const Genome& genome : genomes) {
                ++conversions[{genome[0], attempt}];
                const bool off = genome[0] == 52.5 || (genome[0] == 55.0 && attempt == 0);
                images.push_back(greyOfLightness(off ? 50.5 : genome[0]));
            }
            return images;
        },
        2, 2.0};
    auto delivered =
        checkDelivery(archive, std::move(chosen).value(), request, target, renderGreys, format);
    ASSERT_TRUE(delivered.ok()) << delivered.error().message;
    const VariantSet& set = delivered->set;
    const DeliveredSet& looks = delivered->delivered;
    ASSERT_EQ(set.variants.size(), 3u);
    ASSERT_EQ(looks.variants.size(), 3u);
    EXPECT_EQ(looks.refitted, 1u);
    EXPECT_EQ(looks.replaced, 1u);
    std::vector<double> kept;
    for (std::size_t i = 0; i < 3; ++i) {
        kept.push_back(set.variants[i].genome[0]);
        EXPECT_TRUE(request.band.contains(set.variants[i].deltaEToTarget)) << i;
        EXPECT_TRUE(request.band.contains(looks.variants[i].deltaEToTarget)) << i;
        EXPECT_EQ(looks.variants[i].attempt, kept.back() == 55.0 ? 1 : 0);
    }
    EXPECT_EQ(kept, (std::vector<double>{55.0, 44.5, 47.0}));
    EXPECT_GE(set.smallestPairwise, request.minApart);
    EXPECT_GE(looks.smallestPairwise, request.minApart);
    // The replaced variant had both conversions; nothing was converted twice.
    EXPECT_EQ(conversions[std::pair(52.5, 1)], 1);
    for (const auto& [key, count] : conversions) EXPECT_LE(count, 2) << key.first;
}

// A conversion that holds but misses its own goal is tried again: the refit is delivered when it
// holds within the goal, else the first conversion stays.
TEST(DeliveryCheck, AConversionPastItsGoalIsRefittedAndKeptOnlyWhenTheRefitIsWithin) {
    VariantRequest request;
    request.count = 2;
    request.band = {2.0, 9.0};
    request.minApart = 2.0;
    const Genome target = genomeOfLightness(50.0);
    const LabImage targetLab = toLabImage(greyOfLightness(50.0));
    VariantArchive archive(request.minApart);
    for (double lightness : {56.0, 44.0}) {
        const LabsPerLighting labs{toLabImage(greyOfLightness(lightness))};
        archive.offer(genomeOfLightness(lightness), labs, {meanDeltaE00(targetLab, labs[0])},
                      archive.distancesTo(labs));
    }
    auto chosen = chooseVariantSet(archive, request, target, RenderGenomes(renderGreys));
    ASSERT_TRUE(chosen.ok());
    // Both convert 2.5 L* off at first; only 56's refit comes back within 2 of matevo's render.
    DeliveryFormat format{
        "grey",
        [&](std::span<const Genome> genomes, int attempt) -> Result<std::vector<Image>> {
            std::vector<Image> images;
            for (const Genome& genome : genomes) {
                const bool near = genome[0] == 50.0 || (genome[0] == 56.0 && attempt == 1);
                images.push_back(greyOfLightness(genome[0] + (near ? 0.5 : 2.5)));
            }
            return images;
        },
        2, 2.0};
    auto delivered =
        checkDelivery(archive, std::move(chosen).value(), request, target, renderGreys, format);
    ASSERT_TRUE(delivered.ok()) << delivered.error().message;
    const DeliveredSet& looks = delivered->delivered;
    ASSERT_EQ(looks.variants.size(), 2u);
    EXPECT_EQ(looks.refitted, 1u);
    EXPECT_EQ(looks.replaced, 0u);
    for (std::size_t i = 0; i < 2; ++i) {
        const bool brighter = delivered->set.variants[i].genome[0] == 56.0;
        EXPECT_EQ(looks.variants[i].attempt, brighter ? 1 : 0) << i;
        EXPECT_EQ(looks.withinGoal(i), brighter) << i;
    }
}

}  // namespace
}  // namespace matevo

namespace matevo {
namespace {

// The editor's Export set delivers the user's set as it is: every variant is delivered, none is
// replaced; one whose first conversion leaves the band is refitted, and the check says which
// still hold as delivered.
TEST(DeliveryCheck, ASetDeliveredAsItIsKeepsEveryVariantAndSaysWhichHold) {
    VariantRequest request;
    request.band = {2.0, 8.0};
    request.minApart = 2.0;
    const Genome target = genomeOfLightness(50.0);
    const std::vector<Genome> genomes{genomeOfLightness(55.0), genomeOfLightness(44.5),
                                      genomeOfLightness(47.0)};
    auto set = measureVariantSet(target, genomes, RenderGenomes(renderGreys));
    ASSERT_TRUE(set.ok());
    // 55 converts to 50.5 (out of the band) at first and right when refitted; 44.5 converts to
    // 46.5 every time: in band, but 0.5 L* from 47.
    std::map<std::pair<double, int>, int> conversions;
    const DeliveryFormat format{
        "grey",
        [&](std::span<const Genome> asked, int attempt) -> Result<std::vector<Image>> {
            std::vector<Image> images;
            for (const Genome& genome : asked) {
                ++conversions[{genome[0], attempt}];
                const double look = genome[0] == 55.0 && attempt == 0 ? 50.5
                                    : genome[0] == 44.5               ? 46.5
                                                                      : genome[0];
                images.push_back(greyOfLightness(look));
            }
            return images;
        },
        2, 2.0};
    auto delivered = deliverSetAsItIs(std::move(set).value(), request, target, format);
    ASSERT_TRUE(delivered.ok()) << delivered.error().message;
    ASSERT_EQ(delivered->variants.size(), 3u) << "nothing is dropped";
    EXPECT_EQ(delivered->replaced, 0u);
    EXPECT_EQ(delivered->variants[0].attempt, 1) << "refitted into the band";
    EXPECT_TRUE(deliveredHolds(*delivered, 0, request));
    // 44.5 and 47 are both delivered, too close: neither holds; each tried its refit too.
    EXPECT_FALSE(deliveredHolds(*delivered, 1, request));
    EXPECT_FALSE(deliveredHolds(*delivered, 2, request));
    EXPECT_EQ(conversions[std::pair(47.0, 1)], 1);
    EXPECT_LT(delivered->pairwise[1][2], request.minApart);
}

}  // namespace
}  // namespace matevo
