// Where two sequences differ: hunks between stretches of pairwise equal elements, found after
// insertions, removals and replacements, and one hunk up to the common tail when the
// sequences do not agree again within the search window.
#include "SequenceDiff.h"

#include <string>

#include <gtest/gtest.h>

namespace matevo::testing {
namespace {

using ui::DiffHunk;

std::vector<DiffHunk> diff(const std::string& before, const std::string& after,
                           std::size_t window = 64) {
    return ui::differingStretches(
        before.size(), after.size(),
        [&](std::size_t i, std::size_t j) { return before[i] == after[j]; }, window);
}

// Rebuilds `after` from `before` and the hunks: what lies between hunks must be equal.
std::string apply(const std::string& before, const std::string& after,
                  const std::vector<DiffHunk>& hunks) {
    std::string result;
    std::size_t i = 0, j = 0;
    for (const DiffHunk& hunk : hunks) {
        EXPECT_EQ(hunk.oldBegin - i, hunk.newBegin - j) << "equal stretches pair one to one";
        result += before.substr(i, hunk.oldBegin - i);
        result += after.substr(hunk.newBegin, hunk.newEnd - hunk.newBegin);
        i = hunk.oldEnd;
        j = hunk.newEnd;
    }
    EXPECT_EQ(before.size() - i, after.size() - j);
    result += before.substr(i);
    return result;
}

TEST(SequenceDiff, EqualSequencesHaveNoHunk) {
    EXPECT_TRUE(diff("abcdef", "abcdef").empty());
    EXPECT_TRUE(diff("", "").empty());
}

TEST(SequenceDiff, AReplacedElementIsOneHunkOfOne) {
    const auto hunks = diff("counter 41 of 50", "counter 42 of 50");
    ASSERT_EQ(hunks.size(), 1u);
    EXPECT_EQ(hunks[0], (DiffHunk{9, 10, 9, 10}));
}

TEST(SequenceDiff, InsertionsAndRemovalsShiftWhatFollowsWithoutChangingIt) {
    const std::string before = "run 9 of 50, best 1.5, mean 3.25";
    const std::string after = "run 10 of 50, best 1.5, mean 3.5";
    const auto hunks = diff(before, after);
    ASSERT_EQ(hunks.size(), 2u);
    EXPECT_EQ(apply(before, after, hunks), after);
    std::size_t changed = 0;
    for (const DiffHunk& hunk : hunks)
        changed += (hunk.oldEnd - hunk.oldBegin) + (hunk.newEnd - hunk.newBegin);
    EXPECT_LE(changed, 5u) << "only the digits that differ";
    EXPECT_EQ(apply("", "abc", diff("", "abc")), "abc");
    EXPECT_EQ(apply("abc", "", diff("abc", "")), "");
    EXPECT_EQ(apply("abcdef", "abcdefgh", diff("abcdef", "abcdefgh")), "abcdefgh");
}

TEST(SequenceDiff, BeyondTheWindowTheRestUpToTheCommonTailIsOneHunk) {
    const std::string before = "head " + std::string(40, 'x') + " tail";
    const std::string after = "head " + std::string(40, 'y') + " tail";
    const auto hunks = diff(before, after, 8);
    ASSERT_EQ(hunks.size(), 1u);
    EXPECT_EQ(hunks[0], (DiffHunk{5, 45, 5, 45}));
    EXPECT_EQ(apply(before, after, hunks), after);
}

TEST(SequenceDiff, ScatteredChangesRebuildTheNewSequence) {
    // Every hunk list must rebuild the new sequence, whatever it pairs up.
    const std::string before = "the quick brown fox jumps over the lazy dog, twice or thrice";
    for (const std::string& after :
         std::vector<std::string>{"the quick red fox jumped over a lazy dog, twice or thrice",
                                  "a slow brown fox jumps over the lazy cat, once", "",
                                  "the quick brown fox", "x" + before + "y"}) {
        EXPECT_EQ(apply(before, after, diff(before, after)), after);
        EXPECT_EQ(apply(before, after, diff(before, after, 2)), after);
    }
}

}  // namespace
}  // namespace matevo::testing
