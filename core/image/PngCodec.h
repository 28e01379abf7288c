#pragma once
// PNG through libpng directly: PNG is what every command reads and writes most, and reading it
// this way keeps OpenImageIO (and its hundreds of libraries) out of those commands' start-up.
#include <cstdint>
#include <string>
#include <string_view>

#include "common/Result.h"
#include "image/DecodedImage.h"

namespace matevo {

// Samples as stored: palettes and grey below 8 bits expanded to 8 bits, a tRNS colour key to
// an alpha channel, 16-bit samples kept; no gamma conversion. Errors are one line (libpng's
// text, or checkSize's error as it is) and do not name the file.
Result<DecodedImage> decodePng(std::string_view bytes, const DecodedSizeCheck& checkSize);

// How a PNG says its samples are encoded: an sRGB chunk, or a gAMA chunk of 1.0 (linear data,
// such as a roughness texture, which a viewer or an importer must not decode as colour).
enum class PngEncodingTag { Srgb, Linear };

// An 8-bit RGBA PNG (straight alpha) of width x height interleaved bytes.
Result<std::string> encodePngRgba8(const std::uint8_t* rgba, int width, int height,
                                   PngEncodingTag tag = PngEncodingTag::Srgb);

}  // namespace matevo
