// Errors carry the kind they were born with (it decides the exit status), and keep it when a
// caller puts its context before the message.
#include <gtest/gtest.h>

#include <type_traits>

#include "common/Result.h"

namespace matevo {
namespace {

// An error without a kind does not compile: every construction site says where it was born.
static_assert(!std::is_constructible_v<Error, std::string>);
static_assert(!std::is_default_constructible_v<Error>);

TEST(Result, EachFactoryGivesItsKind) {
    EXPECT_EQ(badInput("x").kind, ErrorKind::BadInput);
    EXPECT_EQ(environmentError("x").kind, ErrorKind::Environment);
    EXPECT_EQ(internalError("x").kind, ErrorKind::Internal);
    EXPECT_EQ(cancelledError().kind, ErrorKind::Cancelled);
    EXPECT_EQ(badInput("a.png: cannot read").message, "a.png: cannot read");
}

TEST(Result, ContextGoesBeforeTheMessageAndTheKindStays) {
    const Error wrapped = withContext(environmentError("Vulkan: no device found"), "--out");
    EXPECT_EQ(wrapped.message, "--out: Vulkan: no device found");
    EXPECT_EQ(wrapped.kind, ErrorKind::Environment);
    const Result<int> failed = withContext(internalError("broken"), "a.json");
    ASSERT_FALSE(failed.ok());
    EXPECT_EQ(failed.error().kind, ErrorKind::Internal);
    EXPECT_EQ(failed.error().message, "a.json: broken");
}

}  // namespace
}  // namespace matevo
