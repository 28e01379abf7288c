// A choice table gives names to parse, names back, labels and the lists help and messages show.
#include <gtest/gtest.h>

#include <array>

#include "common/Choice.h"

namespace matevo {
namespace {

enum class Fruit { Apple, Pear, Plum };
constexpr std::array<Choice<Fruit>, 3> kFruits{{
    {Fruit::Apple, "apple", "Apple"},
    {Fruit::Pear, "pear", "Pear"},
    {Fruit::Plum, "plum", "Plum"},
}};

TEST(Choice, NamesParseBothWays) {
    EXPECT_EQ(parseChoice(kFruits, "pear"), Fruit::Pear);
    EXPECT_EQ(parseChoice(kFruits, "Pear"), std::nullopt);  // names are exact
    EXPECT_EQ(parseChoice(kFruits, ""), std::nullopt);
    for (const auto& row : kFruits)
        EXPECT_EQ(parseChoice(kFruits, choiceName(kFruits, row.value)), row.value);
    EXPECT_EQ(choiceLabel(kFruits, Fruit::Plum), "Plum");
}

TEST(Choice, ListsForHelpAndMessages) {
    EXPECT_EQ(joinChoiceNames(kFruits, "|"), "apple|pear|plum");
    EXPECT_EQ(choiceNamesInWords(kFruits), "apple, pear or plum");
    EXPECT_EQ(choiceNames(kFruits), (std::vector<std::string>{"apple", "pear", "plum"}));
    EXPECT_EQ(inWords({"one"}), "one");
    EXPECT_EQ(inWords({"one", "two"}), "one or two");
}

}  // namespace
}  // namespace matevo
