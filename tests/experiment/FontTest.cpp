#include "image/Font.h"

#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "support/ScopedEnvironment.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

Font dejaVuSans() {
    auto font = Font::dejaVuSans();
    if (!font) throw std::runtime_error(font.error().message);
    return std::move(font).value();
}

// Columns of ink per row (coverage at least one half) of text drawn at 40 pixels per em.
std::map<int, int> inkPerRow(const Font& font, std::string_view text) {
    std::map<int, int> rows;
    font.rasterize(0, 40, text, 40, [&](int, int y, float coverage) {
        if (coverage >= 0.5f) ++rows[y];
    });
    return rows;
}

TEST(Font, DecodesUtf8AndReplacesMalformedBytes) {
    EXPECT_EQ(decodeUtf8("\u0394E00"), (std::vector<char32_t>{0x394, 'E', '0', '0'}));
    EXPECT_EQ(decodeUtf8("\u2013\U0001F600"), (std::vector<char32_t>{0x2013, 0x1F600}));
    EXPECT_EQ(decodeUtf8("a\xCE"), (std::vector<char32_t>{'a', 0xFFFD}));
    EXPECT_EQ(decodeUtf8("\xCE"
                         "A"),
              (std::vector<char32_t>{0xFFFD, 'A'}));
}

// The Greek capital delta is the font's own glyph, a triangle (its narrow top rows widen
// towards the base), not the box drawn for a character the font lacks.
TEST(Font, DrawsTheDeltaOfDeltaE00AsATriangle) {
    const Font font = dejaVuSans();
    EXPECT_TRUE(font.hasGlyph(0x394));
    EXPECT_FALSE(font.hasGlyph(0x10FFFD));
    const std::map<int, int> delta = inkPerRow(font, "\u0394");
    ASSERT_GT(delta.size(), 20u);
    const int topWidth = delta.begin()->second;
    const int baseWidth = std::next(delta.rbegin())->second;  // the row above the last
    EXPECT_GT(baseWidth, 4 * topWidth);
    // The missing-glyph box has the same width at its top and its bottom.
    const std::map<int, int> missing = inkPerRow(font, "\U0010FFFD");
    ASSERT_FALSE(missing.empty());
    EXPECT_EQ(missing.begin()->second, missing.rbegin()->second);
}

TEST(Font, WidthsFollowTheFontsAdvancesAndScaleWithSize) {
    const Font font = dejaVuSans();
    EXPECT_EQ(font.textWidth("", 20), 0.0);
    EXPECT_GT(font.textWidth("\u0394E00", 20), font.textWidth("E00", 20));
    EXPECT_GT(font.textWidth("WWW", 20), font.textWidth("iii", 20));
    EXPECT_NEAR(font.textWidth("mean \u0394E00", 30), 1.5 * font.textWidth("mean \u0394E00", 20),
                1e-6);
}

TEST(Font, WithoutTheFontTheMessageSaysWhereItLookedAndWhichPackageHasIt) {
    matevo::testing::ScratchFolder scratch("font");
    testing::ScopedEnvironment dataHome("XDG_DATA_HOME", (scratch / "home").string());
    testing::ScopedEnvironment dataDirs("XDG_DATA_DIRS",
                                        (scratch / "a").string() + ":" + (scratch / "b").string());
    auto font = Font::dejaVuSans();
    ASSERT_FALSE(font);
    const std::string& message = font.error().message;
    EXPECT_NE(message.find("fonts-dejavu-core"), std::string::npos) << message;
    for (const char* dir : {"home", "a", "b"})
        EXPECT_NE(message.find((scratch / dir / "fonts/truetype/dejavu/DejaVuSans.ttf").string()),
                  std::string::npos)
            << message;

    // A file there that is not a font is named as such.
    std::filesystem::create_directories(scratch / "b/fonts/truetype/dejavu");
    std::ofstream(scratch / "b/fonts/truetype/dejavu/DejaVuSans.ttf") << "not a font";
    auto notFont = Font::dejaVuSans();
    ASSERT_FALSE(notFont);
    EXPECT_NE(notFont.error().message.find("DejaVuSans.ttf"), std::string::npos);
    EXPECT_NE(notFont.error().message.find("not a TrueType font"), std::string::npos);
}

}  // namespace
}  // namespace matevo
