#pragma once
// Text in a real font for the images matevo draws (experiment charts, variant contact sheets):
// DejaVu Sans from Debian's fonts-dejavu-core, rasterised by stb_truetype as Debian's
// libimgui-dev ships it (imstb_truetype.h: a standalone rasteriser, no ImGui code). Any
// character the font has is drawn, ΔE00 included; OpenImageIO's render_text is not used because
// Debian's 2.4.7 decodes UTF-8 wrongly and draws a missing glyph for every non-ASCII character.
#include <filesystem>
#include <functional>
#include <memory>
#include <string_view>
#include <vector>

#include "common/Result.h"

namespace matevo {

class Font {
public:
    // The first face of a TrueType file; the message names the file when it is not one.
    static Result<Font> load(const std::filesystem::path& file);
    // DejaVu Sans: fonts/truetype/dejavu/DejaVuSans.ttf under $XDG_DATA_HOME (default
    // ~/.local/share) and each of $XDG_DATA_DIRS (default /usr/local/share:/usr/share); the
    // message lists where it looked.
    static Result<Font> dejaVuSans();
    // The family name SVG files give for this font (with a generic fallback).
    static constexpr std::string_view kSvgFamily = "DejaVu Sans, Verdana, sans-serif";

    // Whether the font draws this code point (rather than its missing-glyph box).
    bool hasGlyph(char32_t codePoint) const;
    // The advance of UTF-8 text in pixels at `size` pixels per em (SVG's font-size).
    double textWidth(std::string_view text, double size) const;
    // Rasterises UTF-8 text from the left end of its baseline at (x, baseline): `plot` gets
    // each pixel the glyphs touch with their coverage in (0, 1] (anti-aliased edges).
    using PlotPixel = std::function<void(int x, int y, float coverage)>;
    void rasterize(double x, double baseline, std::string_view text, double size,
                   const PlotPixel& plot) const;

private:
    struct Face;
    explicit Font(std::shared_ptr<const Face> face) : face_(std::move(face)) {}
    std::shared_ptr<const Face> face_;
};

// Code points of UTF-8 text; a malformed byte becomes U+FFFD.
std::vector<char32_t> decodeUtf8(std::string_view text);

}  // namespace matevo
