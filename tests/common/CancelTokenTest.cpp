// A token's copies share one state; it says why it was cancelled, and the first reason stays.
#include <gtest/gtest.h>

#include "common/CancelToken.h"

namespace matevo {
namespace {

TEST(CancelToken, CopiesShareTheStopAndItsReason) {
    const CancelToken token;
    const CancelToken copy = token;
    EXPECT_FALSE(copy.cancelled());
    EXPECT_EQ(copy.reason(), CancelReason::None);
    token.cancel(CancelReason::MemoryLimit);
    EXPECT_TRUE(copy.cancelled());
    EXPECT_EQ(copy.reason(), CancelReason::MemoryLimit);
}

TEST(CancelToken, TheFirstReasonStays) {
    const CancelToken token;
    token.cancel();
    token.cancel(CancelReason::MemoryLimit);
    EXPECT_EQ(token.reason(), CancelReason::Request);
    CancelToken::cancelState(*token.state(), CancelReason::MemoryLimit);  // as a signal handler
    EXPECT_EQ(token.reason(), CancelReason::Request);
}

}  // namespace
}  // namespace matevo
