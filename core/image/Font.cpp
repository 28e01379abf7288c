#include "image/Font.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "files/InputFile.h"
#include "files/XdgFolders.h"

// stb_truetype's implementation, private to this file.
#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <imgui/imstb_truetype.h>

namespace matevo {

struct Font::Face {
    std::string bytes;  // stbtt_fontinfo points into it
    stbtt_fontinfo info{};
};

namespace {

constexpr std::uintmax_t kMaxFontBytes = 64u << 20;

}  // namespace

std::vector<char32_t> decodeUtf8(std::string_view text) {
    constexpr char32_t kReplacement = 0xFFFD;
    std::vector<char32_t> codePoints;
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const int length = lead < 0x80         ? 1
                           : lead >> 5 == 0x6  ? 2
                           : lead >> 4 == 0xE  ? 3
                           : lead >> 3 == 0x1E ? 4
                                               : 0;
        if (length == 0 || i + std::size_t(length) > text.size()) {
            codePoints.push_back(kReplacement);
            ++i;
            continue;
        }
        char32_t codePoint = length == 1 ? lead : lead & (0x7F >> length);
        bool wellFormed = true;
        for (int k = 1; k < length; ++k) {
            const auto next = static_cast<unsigned char>(text[i + std::size_t(k)]);
            wellFormed = wellFormed && (next & 0xC0) == 0x80;
            codePoint = (codePoint << 6) | (next & 0x3F);
        }
        codePoints.push_back(wellFormed ? codePoint : kReplacement);
        i += wellFormed ? std::size_t(length) : 1;
    }
    return codePoints;
}

Result<Font> Font::load(const std::filesystem::path& file) {
    auto bytes = readInputFile(file, kMaxFontBytes);
    if (!bytes) return bytes.error();
    auto face = std::make_shared<Face>();
    face->bytes = std::move(bytes).value();
    const auto* data = reinterpret_cast<const unsigned char*>(face->bytes.data());
    const int offset = stbtt_GetFontOffsetForIndex(data, 0);
    if (offset < 0 || !stbtt_InitFont(&face->info, data, offset))
        return badInput(displayPath(file) + ": not a TrueType font");
    return Font(std::move(face));
}

Result<Font> Font::dejaVuSans() {
    const std::filesystem::path relative = "fonts/truetype/dejavu/DejaVuSans.ttf";
    std::string looked;
    for (const auto& dir : xdgDataSearchPath()) {
        const std::filesystem::path file = dir / relative;
        std::error_code error;
        if (std::filesystem::is_regular_file(file, error)) return load(file);
        looked += (looked.empty() ? "" : ", ") + file.string();
    }
    return badInput("cannot find the DejaVu Sans font (Debian: fonts-dejavu-core); looked in " +
                    looked);
}

bool Font::hasGlyph(char32_t codePoint) const {
    return stbtt_FindGlyphIndex(&face_->info, int(codePoint)) != 0;
}

double Font::textWidth(std::string_view text, double size) const {
    const double scale = stbtt_ScaleForMappingEmToPixels(&face_->info, float(size));
    double width = 0;
    int previous = 0;
    for (char32_t codePoint : decodeUtf8(text)) {
        const int glyph = stbtt_FindGlyphIndex(&face_->info, int(codePoint));
        int advance = 0, leftBearing = 0;
        stbtt_GetGlyphHMetrics(&face_->info, glyph, &advance, &leftBearing);
        if (previous) width += scale * stbtt_GetGlyphKernAdvance(&face_->info, previous, glyph);
        width += scale * advance;
        previous = glyph;
    }
    return width;
}

void Font::rasterize(double x, double baseline, std::string_view text, double size,
                     const PlotPixel& plot) const {
    const stbtt_fontinfo& info = face_->info;
    const float scale = stbtt_ScaleForMappingEmToPixels(&info, float(size));
    const int baselineRow = int(std::lround(baseline));
    std::vector<unsigned char> coverage;
    int previous = 0;
    for (char32_t codePoint : decodeUtf8(text)) {
        const int glyph = stbtt_FindGlyphIndex(&info, int(codePoint));
        if (previous) x += double(scale) * stbtt_GetGlyphKernAdvance(&info, previous, glyph);
        previous = glyph;
        // Each glyph at its own sub-pixel offset, so spacing follows the font's advances.
        const int penX = int(std::floor(x));
        const float shiftX = float(x - penX);
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        stbtt_GetGlyphBitmapBoxSubpixel(&info, glyph, scale, scale, shiftX, 0, &x0, &y0, &x1, &y1);
        const int width = x1 - x0, height = y1 - y0;
        if (width > 0 && height > 0) {
            coverage.assign(std::size_t(width) * std::size_t(height), 0);
            stbtt_MakeGlyphBitmapSubpixel(&info, coverage.data(), width, height, width, scale,
                                          scale, shiftX, 0, glyph);
            for (int row = 0; row < height; ++row)
                for (int column = 0; column < width; ++column)
                    if (const unsigned char value =
                            coverage[std::size_t(row) * std::size_t(width) + std::size_t(column)])
                        plot(penX + x0 + column, baselineRow + y0 + row, value / 255.0f);
        }
        int advance = 0, leftBearing = 0;
        stbtt_GetGlyphHMetrics(&info, glyph, &advance, &leftBearing);
        x += double(scale) * advance;
    }
}

}  // namespace matevo
