#include "genome/Genome.h"

#include <gtest/gtest.h>

namespace matevo {
namespace {

TEST(Genome, ChromosomeNamesFollowTheCommandLineOrder) {
    EXPECT_EQ(chromosomeName(kEta1), "eta1");
    EXPECT_EQ(chromosomeName(kSigmaSR), "sigma_s_r");
    EXPECT_EQ(chromosomeName(kG), "g");
    EXPECT_EQ(chromosomeName(kKappaB), "kappa_b");
    EXPECT_EQ(chromosomeName(kChromosomeCount), "?");
}

}  // namespace
}  // namespace matevo
