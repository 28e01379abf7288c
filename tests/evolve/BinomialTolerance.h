#pragma once
// Operator statistics: an observed count of successes is consistent with probability p when it
// lies within five binomial standard deviations of n p (fixed seeds, so never flaky).
#include <cmath>

#include <gtest/gtest.h>

namespace matevo {

inline ::testing::AssertionResult matchesProbability(long hits, long trials, double p) {
    const double expected = static_cast<double>(trials) * p;
    const double sigma = std::sqrt(static_cast<double>(trials) * p * (1 - p));
    if (std::abs(static_cast<double>(hits) - expected) <= 5 * sigma)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << hits << " of " << trials << " is not p = " << p
                                         << " (expected " << expected << " +- " << 5 * sigma << ")";
}

}  // namespace matevo
