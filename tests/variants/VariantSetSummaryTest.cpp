// A set's figures as the user reads them: a given set measured as it is, and a summary line that
// claims only what holds (kept materials join a set as they are, in band or not, apart or not).
#include <gtest/gtest.h>

#include "variants/VariantFiles.h"
#include "variants/VariantSet.h"

namespace matevo {
namespace {

// Each genome drawn as a flat grey of its alpha1: distances follow the genes.
Result<std::vector<Image>> flatGreys(std::span<const Genome> genomes) {
    std::vector<Image> images;
    for (const Genome& genome : genomes) {
        Image image(4, 4);
        for (std::size_t i = 0; i < image.rgba.size(); ++i)
            image.rgba[i] = i % 4 == 3 ? 1.0f : float(genome.alpha1());
        images.push_back(std::move(image));
    }
    return images;
}

Genome withAlpha1(double alpha1) {
    Genome genome;
    genome[kAlpha1] = alpha1;
    return genome;
}

TEST(MeasureVariantSet, KeepsEveryMemberInOrderWithItsDistances) {
    const std::vector<Genome> members{withAlpha1(0.3), withAlpha1(0.31), withAlpha1(0.6)};
    auto set = measureVariantSet(withAlpha1(0.2), members, flatGreys);
    ASSERT_TRUE(set.ok()) << set.error().message;
    ASSERT_EQ(set->variants.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(set->variants[i].genome, members[i]);
    EXPECT_GT(set->variants[2].deltaEToTarget, set->variants[0].deltaEToTarget);
    EXPECT_DOUBLE_EQ(set->pairwise[0][1], set->pairwise[1][0]);
    EXPECT_DOUBLE_EQ(set->smallestPairwise, set->pairwise[0][1]) << "the two near greys";
}

TEST(VariantSummary, SaysOnlyWhatHolds) {
    const std::vector<Genome> members{withAlpha1(0.3), withAlpha1(0.31), withAlpha1(0.6)};
    const VariantSet set = *measureVariantSet(withAlpha1(0.2), members, flatGreys);
    VariantRun run;
    run.request.count = 3;
    run.request.minApart = set.smallestPairwise + 1.0;  // the two near greys are closer
    run.request.band = {0.0, set.variants[1].deltaEToTarget + 0.01};  // the third is outside
    const std::string text = variantSummary(run, set);
    EXPECT_EQ(text.find("apart"), std::string::npos) << text;
    EXPECT_NE(text.find("2 in band"), std::string::npos) << text;
    EXPECT_NE(text.find("(asked at least"), std::string::npos) << text;
    // All holding: the usual line.
    run.request.minApart = 0.0;
    run.request.band = {0.0, 1000.0};
    EXPECT_NE(variantSummary(run, set).find("3 of 3 variants in band 0-1000, at least 0 apart"),
              std::string::npos)
        << variantSummary(run, set);
}

}  // namespace
}  // namespace matevo
