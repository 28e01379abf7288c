#include "genome/FamilyRules.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "TestGenomes.h"

namespace matevo {
namespace {

constexpr MaterialFamily kRoughcoatDielectric{Coat::Roughcoat, Base::Dielectric, false,
                                              TexturedLayer::None};
constexpr MaterialFamily kClearcoatDielectric{Coat::Clearcoat, Base::Dielectric, false,
                                              TexturedLayer::None};

// The message must name the chromosome and say what is wrong.
void expectRejected(const Genome& genome, const MaterialFamily& family, const std::string& name,
                    const std::string& rule) {
    const auto problem = validateGenome(genome, family);
    ASSERT_TRUE(problem.has_value()) << "accepted, expected a complaint about " << name;
    EXPECT_NE(problem->find(name), std::string::npos) << *problem;
    EXPECT_NE(problem->find(rule), std::string::npos) << *problem;
}

TEST(FamilyRules, ThePapersValidationMaterialsAreValid) {
    EXPECT_TRUE(satisfiesTable2(validationMetal(), kClearcoatConductor));
    EXPECT_TRUE(satisfiesTable2(genomeOf(1.2, 0.8, 2.5, 0.099), kPaintedMetal));
    EXPECT_TRUE(satisfiesTable2(validationMetalDepth(), kMetalDepth));
}

TEST(FamilyRules, Table2RangesPerCoatAndBase) {
    const auto range = [](const MaterialFamily& family, std::size_t index) {
        return describe(chromosomeRange(family, index));
    };
    EXPECT_EQ(range(kClearcoatConductor, kAlpha1), "[0, 0.1)");
    EXPECT_EQ(range(kClearcoatConductor, kAlpha2), "[0.1, 1]");
    EXPECT_EQ(range(kClearcoatConductor, kEta1), "(1, 2]");
    EXPECT_EQ(range(kClearcoatDielectric, kAlpha1), "[0, 0.01)");
    EXPECT_EQ(range(kClearcoatDielectric, kAlpha2), "[0.01, 1]");
    EXPECT_EQ(range(kClearcoatDielectric, kEta1), "(1, 3]");
    EXPECT_EQ(range(kRoughcoatDielectric, kAlpha1), "[0.1, 1]");
    EXPECT_EQ(range(kRoughcoatDielectric, kAlpha2), "[0, 0.01)");
    EXPECT_EQ(range(kRoughcoatDielectric, kEta2), "[1, 2.5]");
    EXPECT_EQ(range(kPaintedMetal, kAlpha1), "[0.1, 4]");
    EXPECT_EQ(range(kPaintedMetal, kAlpha2), "[0, 0.1)");
    EXPECT_EQ(range(kMetalDepth, kDepth), "[0.05, 40]");
    EXPECT_EQ(range(kMetalDepth, kSigmaAB), "[0, 1]");
    EXPECT_EQ(range(kMetalDepth, kG), "[0.7, 0.99]");
    EXPECT_EQ(range(kMetalDepth, kEta2), "[0.1, 1)");
    EXPECT_EQ(range(kClearcoatConductor, kEta2), "[0.1, 2)");
}

TEST(FamilyRules, WithoutAMediumTheMediumChromosomesArePinnedToZero) {
    for (std::size_t i = kDepth; i < kPaperChromosomeCount; ++i) {
        const ChromosomeRange range = chromosomeRange(kClearcoatConductor, i);
        EXPECT_FALSE(range.active) << chromosomeName(i);
        EXPECT_EQ(range.min, 0.0);
        EXPECT_EQ(range.max, 0.0);
        EXPECT_TRUE(chromosomeRange(kMetalDepth, i).active) << chromosomeName(i);
    }
    Genome genome = genomeOf(1.2, 0.8, 0.03, 0.1);
    genome[kG] = 0.8;
    expectRejected(genome, kClearcoatConductor, "g", "no medium");
}

// Hue variety: the kappa genes are off (pinned to 0) unless asked for, and then active in
// their stated bounds for a conductor base only.
TEST(FamilyRules, KappaGenesAreOffByDefaultAndBoundedWhenOn) {
    for (const MaterialFamily& family : supportedFamilies()) {
        const FamilyRules paper = familyRules(family);
        const FamilyRules hue = familyRules(family, KappaGenes::On);
        for (std::size_t i = 0; i < kPaperChromosomeCount; ++i)
            EXPECT_EQ(describe(paper.ranges[i]), describe(hue.ranges[i])) << chromosomeName(i);
        for (std::size_t i = kKappaR; i <= kKappaB; ++i) {
            EXPECT_FALSE(paper.ranges[i].active) << describe(family);
            EXPECT_EQ(paper.ranges[i].min, 0.0);
            EXPECT_EQ(hue.ranges[i].active, family.base == Base::Conductor) << describe(family);
            if (family.base == Base::Conductor) {
                EXPECT_EQ(describe(hue.ranges[i]), "[1, 4]");
            }
        }
    }
    Genome tinted = genomeOf(1.2, 0.8, 0.03, 0.1);
    tinted[kKappaG] = 2.0;
    expectRejected(tinted, kClearcoatConductor, "kappa_g", "kappa genes are off");
    const FamilyRules hue = familyRules(kClearcoatConductor, KappaGenes::On);
    tinted[kKappaR] = tinted[kKappaB] = 1.0;
    EXPECT_EQ(validateGenome(tinted, hue), std::nullopt);
    tinted[kKappaB] = 4.5;
    ASSERT_TRUE(validateGenome(tinted, hue));
    EXPECT_NE(validateGenome(tinted, hue)->find("kappa_b = 4.5 is outside [1, 4]"),
              std::string::npos);
}

TEST(FamilyRules, EachRangeEndIsInclusiveOrExclusiveAsTable2Says) {
    expectRejected(genomeOf(1.0, 0.8, 0.03, 0.1), kClearcoatConductor, "eta1", "(1, 2]");
    EXPECT_EQ(validateGenome(genomeOf(2.0, 0.8, 0.03, 0.1), kClearcoatConductor), std::nullopt);
    expectRejected(genomeOf(1.2, 0.8, 0.1, 0.1), kClearcoatConductor, "alpha1", "[0, 0.1)");
    EXPECT_EQ(validateGenome(genomeOf(1.2, 0.8, 0.0, 0.1), kClearcoatConductor), std::nullopt);
    expectRejected(genomeOf(1.2, 0.8, 0.03, 0.0999), kClearcoatConductor, "alpha2", "[0.1, 1]");
    expectRejected(genomeOf(1.2, 0.8, 4.01, 0.05), kPaintedMetal, "alpha1", "[0.1, 4]");
    Genome deep = validationMetalDepth();
    deep[kDepth] = 40.5;
    expectRejected(deep, kMetalDepth, "depth", "[0.05, 40]");
    deep = validationMetalDepth();
    deep[kSigmaAG] = -0.01;
    expectRejected(deep, kMetalDepth, "sigma_a_g", "[0, 1]");
}

TEST(FamilyRules, ConductorEta2LiesBelowEta1WithinOneAndAHalf) {
    EXPECT_EQ(validateGenome(genomeOf(1.9, 0.4, 0.03, 0.1), kClearcoatConductor), std::nullopt);
    expectRejected(genomeOf(1.9, 0.39, 0.03, 0.1), kClearcoatConductor, "eta2", "footnote a");
    expectRejected(genomeOf(1.2, 1.2, 0.03, 0.1), kClearcoatConductor, "eta2", "below");
    expectRejected(genomeOf(1.2, 1.3, 0.03, 0.1), kClearcoatConductor, "eta2", "below");
}

TEST(FamilyRules, ConductorUnderAMediumNeedsEta2BelowOne) {
    Genome genome = validationMetalDepth();
    genome[kEta1] = 1.9;
    genome[kEta2] = 1.0;
    expectRejected(genome, kMetalDepth, "eta2", "[0.1, 1)");
    genome[kEta2] = 0.99;
    EXPECT_EQ(validateGenome(genome, kMetalDepth), std::nullopt);
}

TEST(FamilyRules, DielectricEta2LiesAboveEta1) {
    EXPECT_EQ(validateGenome(genomeOf(1.5, 2.0, 0.3, 0.005), kRoughcoatDielectric), std::nullopt);
    expectRejected(genomeOf(1.5, 2.01, 0.3, 0.005), kRoughcoatDielectric, "eta2", "footnote b");
    expectRejected(genomeOf(1.5, 1.4, 0.3, 0.005), kRoughcoatDielectric, "eta2", "above");
    EXPECT_EQ(validateGenome(genomeOf(2.5, 5.5, 0.005, 0.5), kClearcoatDielectric), std::nullopt);
    expectRejected(genomeOf(2.5, 5.6, 0.005, 0.5), kClearcoatDielectric, "eta2", "(0, 3]");
}

TEST(FamilyRules, NotANumberIsNeverValid) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expectRejected(genomeOf(1.2, nan, 0.03, 0.1), kClearcoatConductor, "eta2", "nan");
    Genome genome = validationMetalDepth();
    genome[kG] = nan;
    expectRejected(genome, kMetalDepth, "g", "[0.7, 0.99]");
}

TEST(FamilyRules, EtaIntervalsFollowTheRelationAndTheAbsoluteRange) {
    const FamilyRules conductor = familyRules(kClearcoatConductor);
    EXPECT_EQ(describe(conductor.eta2Given(1.2)), "[0.1, 1.2)");
    EXPECT_EQ(describe(conductor.eta2Given(1.8)), "[0.3, 1.8)");
    EXPECT_EQ(describe(conductor.eta1Given(0.8)), "(1, 2]");
    EXPECT_EQ(describe(conductor.eta1Given(0.2)), "(1, 1.7]");
    const FamilyRules dielectric = familyRules(kRoughcoatDielectric);
    EXPECT_EQ(describe(dielectric.eta2Given(1.5)), "(1.5, 2]");
    EXPECT_EQ(describe(dielectric.eta1Given(2.2)), "[1.7, 2]");
    EXPECT_EQ(describe(familyRules(kMetalDepth).eta2Given(1.8)), "[0.3, 1)");
}

TEST(FamilyRules, IntersectionKeepsTheStricterEnd) {
    const ChromosomeRange a{0.0, 1.0, true, true, true};
    const ChromosomeRange b{0.0, 2.0, false, true, true};
    const ChromosomeRange both = intersect(a, b);
    EXPECT_EQ(describe(both), "(0, 1]");
    EXPECT_FALSE(both.contains(0.0));
    EXPECT_TRUE(both.contains(1.0));
    EXPECT_TRUE((ChromosomeRange{1.0, 1.0, true, false, true}).empty());
    EXPECT_FALSE((ChromosomeRange{1.0, 1.0, true, true, true}).empty());
}

TEST(FamilyRules, TexturingGoesWithTheRoughLayer) {
    const auto families = supportedFamilies();
    EXPECT_EQ(families.size(), 16u);
    for (const auto& family : families) {
        if (family.texturedLayer == TexturedLayer::Top) {
            EXPECT_EQ(family.coat, Coat::Roughcoat);
        }
        if (family.texturedLayer == TexturedLayer::Bottom) {
            EXPECT_EQ(family.coat, Coat::Clearcoat);
        }
    }
    const MaterialFamily clearcoatTop{Coat::Clearcoat, Base::Conductor, false, TexturedLayer::Top};
    ASSERT_TRUE(validateFamily(clearcoatTop).has_value());
    EXPECT_NE(validateGenome(genomeOf(1.2, 0.8, 0.03, 0.1), clearcoatTop)->find("top"),
              std::string::npos);
    const MaterialFamily clearcoatBottom{Coat::Clearcoat, Base::Dielectric, false,
                                         TexturedLayer::Bottom};
    EXPECT_EQ(describe(chromosomeRange(clearcoatBottom, kAlpha2)), "[0.01, 4]");
}

}  // namespace
}  // namespace matevo
