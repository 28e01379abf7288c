#pragma once
// PNG through libpng directly: PNG is what every command reads and writes most, and reading it
// this way keeps OpenImageIO (and its hundreds of libraries) out of those commands' start-up.
#include <cstdint>
#include <string>
#include <string_view>

#include "common/Result.h"
#include "io/DecodedImage.h"

namespace matevo {

// Samples as stored: palettes and grey below 8 bits expanded to 8 bits, a tRNS colour key to
// an alpha channel, 16-bit samples kept; no gamma conversion. Errors are one line (libpng's
// text, or checkSize's error as it is) and do not name the file.
Result<DecodedImage> decodePng(std::string_view bytes, const DecodedSizeCheck& checkSize);

// An 8-bit RGBA PNG (straight alpha, tagged sRGB) of width x height interleaved bytes.
Result<std::string> encodePngRgba8(const std::uint8_t* rgba, int width, int height);

}  // namespace matevo
