#include "common/ByteSize.h"

#include <gtest/gtest.h>

#include "common/MemoryBudget.h"

namespace matevo {
namespace {

TEST(ByteSize, ParsesWholeAmountsWithBinarySuffixes) {
    EXPECT_EQ(parseByteSize("1"), 1u);
    EXPECT_EQ(parseByteSize("64K"), 64u << 10);
    EXPECT_EQ(parseByteSize("512m"), 512u << 20);
    EXPECT_EQ(parseByteSize("16G"), 16ull << 30);
    EXPECT_EQ(parseByteSize("2GiB"), 2ull << 30);
    EXPECT_EQ(parseByteSize("3MB"), 3u << 20);
    EXPECT_EQ(parseByteSize("1T"), 1ull << 40);
    EXPECT_EQ(parseByteSize("8388608T"), 1ull << 63);
}

TEST(ByteSize, RefusesAnythingElse) {
    for (const char* text : {"", "0", "0G", "G", "-1", "1.5G", "16X", "16 G", "16Gb2", "16GiBs",
                             "8388609T", "99999999999999999999", " 16G"})
        EXPECT_FALSE(parseByteSize(text)) << text;
}

TEST(ByteSize, DescribesRoundingUpSoThatPastALimitNeverReadsAsTheLimit) {
    EXPECT_EQ(describeBytes(0), "0 KiB");
    EXPECT_EQ(describeBytes(64u << 10), "64 KiB");
    EXPECT_EQ(describeBytes(512u << 20), "512 MiB");
    EXPECT_EQ(describeBytes((512u << 20) + 1), "512.1 MiB");
    EXPECT_EQ(describeBytes(3ull << 29), "1.5 GiB");
    EXPECT_EQ(describeBytes(~0ull), "17179869184 GiB");
}

TEST(MemoryBudget, TheLimitSetIsTheLimitChecked) {
    setMemoryLimitBytes(1u << 20);
    EXPECT_TRUE(checkMemoryEstimate(1u << 20, "exactly the limit"));
    const auto past = checkMemoryEstimate((1u << 20) + 1, "one byte more");
    ASSERT_FALSE(past);
    EXPECT_EQ(past.error().message,
              "one byte more needs about 1.1 MiB of memory, more than the limit of 1 MiB "
              "(--max-memory raises it, e.g. --max-memory 32G)");
    setMemoryLimitBytes(0);  // back to the default: half the machine, far more than 1 MiB
    EXPECT_GT(memoryLimitBytes(), 1u << 20);
}

}  // namespace
}  // namespace matevo
