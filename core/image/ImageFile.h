#pragma once
// Images on disk: the one image reader and writer. PNG goes through libpng (image/PngCodec.h),
// every other format through OpenImageIO, loaded only then (image/ImageLibrary.h). Integer samples
// (PNG, JPEG, 8/16-bit TIFF) are sRGB-encoded; floating-point samples (OpenEXR, Radiance HDR) are
// linear. In memory an Image is always linear with straight (unassociated) alpha, so colour
// values are stored as they are and alpha is never multiplied in.
#include <filesystem>
#include <string_view>
#include <vector>

#include "common/Image.h"
#include "common/Result.h"

namespace matevo {

struct ImageFileContents {
    Image image;
    // False when the file had no alpha channel; the image then has alpha = 1 everywhere and a
    // comparison should use every pixel.
    bool hasAlpha = false;
};

// Reads any format OpenImageIO reads, chosen by the extension in any case (.png, .PNG, .exr,
// .hdr, .jpg, .tif, ...). Errors are one line naming the file: unsupported extension,
// unreadable, not an image, or an unsupported channel layout.
// Grey files are expanded to RGB.
// Files are read through readInputFile (regular files up to kMaxImageFileBytes); the decoded
// size is checked against the memory limit (common/MemoryBudget.h) before it is allocated, and
// non-finite pixel values are refused.
Result<ImageFileContents> readImageFile(const std::filesystem::path& file);
// The same from bytes already in memory; `file` gives the type (its extension) and the name.
Result<ImageFileContents> decodeImageFile(std::string_view bytes,
                                          const std::filesystem::path& file);
Result<Image> readImage(const std::filesystem::path& file);

// Whether writeImage can write this file's type: .png or .exr, in any case.
bool isWritableImageType(const std::filesystem::path& file);
// Whether writeImage can encode that type here: .png always, .exr when matevo's OpenImageIO
// module loads (the error says where it was looked for). Asked before the work whose result
// is written, so that a long run does not fail at its end.
Status checkImageEncoder(const std::filesystem::path& file);

// Writes RGBA to .png (sRGB-encoded 8 bit, values clamped to [0, 1]) or .exr (32-bit float).
// Atomic: written to a temporary file beside the target, then renamed over it.
Status writeImage(const Image& image, const std::filesystem::path& file);

// PNG file contents in memory (for files that embed images, such as glTF): 8-bit RGBA, the colour
// sRGB-encoded and tagged sRGB (a colour texture) or stored as it is and tagged linear (data,
// such as roughness).
enum class PngValues { Srgb, Linear };
Result<std::vector<unsigned char>> encodePng(const Image& image, PngValues values);

// The image as writeImage stores it in a PNG and readImage returns it (colour through 8-bit sRGB,
// alpha through 8 bits), without the file: figures measured on it are the ones `matevo compare`
// finds in the written files.
Image quantizeAsPng(const Image& image);

}  // namespace matevo
