#include "io/ImageFile.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>
#include <system_error>
#include <vector>

#include "color/Srgb.h"
#include "common/MemoryBudget.h"
#include "io/AtomicFile.h"
#include "io/ExrHeaderCheck.h"
#include "io/InputFile.h"

namespace matevo {
namespace {

enum class FileKind { kPng, kExr, kHdr, kUnsupported };

std::vector<unsigned char> encodeSrgb8(const Image& image) {
    std::vector<unsigned char> bytes(image.rgba.size());
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        double value = std::clamp(double(image.rgba[i]), 0.0, 1.0);
        if (i % 4 != 3) value = linearToSrgb(value);  // alpha is coverage, not light
        bytes[i] = static_cast<unsigned char>(std::lround(value * 255.0));
    }
    return bytes;
}

float decodeSrgb(float encoded) { return float(srgbToLinear(encoded)); }

FileKind kindOf(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".png") return FileKind::kPng;
    if (extension == ".exr") return FileKind::kExr;
    if (extension == ".hdr") return FileKind::kHdr;  // Radiance RGBE: environments, read only
    return FileKind::kUnsupported;
}

// OpenImageIO messages may span lines; our errors are one line.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text.empty() ? std::string("unknown OpenImageIO error") : text;
}

Error fileError(const std::filesystem::path& file, const std::string& what) {
    return Error{displayPath(file) + ": " + what};
}

// Maps an interleaved file pixel of 1-4 channels onto RGBA; grey is replicated.
void expandToRgba(const float* source, int channels, bool hasAlpha, float* rgba) {
    const int colourChannels = hasAlpha ? channels - 1 : channels;
    for (int c = 0; c < 3; ++c) rgba[c] = source[colourChannels == 1 ? 0 : c];
    rgba[3] = hasAlpha ? source[channels - 1] : 1.0f;
}

}  // namespace

Result<ImageFileContents> readImageFile(const std::filesystem::path& file) {
    if (kindOf(file) == FileKind::kUnsupported)
        return fileError(file, "unsupported image type (expected .png or .exr)");
    // Read through the one safe reader (regular files of bounded size only); OpenImageIO then
    // decodes from memory, so it never opens the path itself.
    auto bytes = readInputFile(file, kMaxImageFileBytes);
    if (!bytes) return bytes.error();
    return decodeImageFile(*bytes, file);
}

Result<ImageFileContents> decodeImageFile(std::string_view bytes,
                                          const std::filesystem::path& file) {
    const FileKind kind = kindOf(file);
    if (kind == FileKind::kUnsupported)
        return fileError(file, "unsupported image type (expected .png, .exr or .hdr)");
    if (kind == FileKind::kExr)
        if (auto headers = checkExrHeaders(bytes); !headers)
            return fileError(file, "not a readable OpenEXR image: " + headers.error().message);
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());

    // PNG stores straight alpha; without this hint OpenImageIO would premultiply on read.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    const char* format = kind == FileKind::kPng   ? "png"
                         : kind == FileKind::kHdr ? "hdr"
                                                  : "openexr";
    auto input = OIIO::ImageInput::create(format);
    if (!input || !input->set_ioproxy(&memory))
        return fileError(file, "cannot decode: " + oneLine(OIIO::geterror()));
    OIIO::ImageSpec spec;
    if (!input->open(file.string(), spec, config))
        return fileError(file, std::string("not a readable ") +
                                   (kind == FileKind::kPng   ? "PNG"
                                    : kind == FileKind::kHdr ? "Radiance HDR"
                                                             : "OpenEXR") +
                                   " image: " + oneLine(input->geterror()));

    const int channels = spec.nchannels;
    if (channels < 1 || channels > 4)
        return fileError(file, "unsupported channel count " + std::to_string(channels));
    if (spec.width <= 0 || spec.height <= 0) return fileError(file, "empty image");
    const bool hasAlpha = channels == 2 || channels == 4;
    // The decoded file pixels plus the RGBA image: checked before anything is allocated.
    const std::uint64_t pixelCount = std::uint64_t(spec.width) * std::uint64_t(spec.height);
    if (auto fits =
            checkMemoryEstimate(pixelCount * (std::uint64_t(channels) + 4) * sizeof(float),
                                displayPath(file) + ": decoding " + std::to_string(spec.width) +
                                    "x" + std::to_string(spec.height) + " pixels");
        !fits)
        return fits.error();

    std::vector<float> pixels(std::size_t(pixelCount) * std::size_t(channels));
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        return fileError(file, "cannot decode: " + oneLine(input->geterror()));
    input->close();

    ImageFileContents contents{Image(spec.width, spec.height), hasAlpha};
    const bool srgbEncoded = kind == FileKind::kPng;
    for (std::size_t i = 0; i < contents.image.pixelCount(); ++i) {
        float* rgba = &contents.image.rgba[i * 4];
        expandToRgba(&pixels[i * std::size_t(channels)], channels, hasAlpha, rgba);
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(rgba[c]))
                return fileError(file, "pixel (" + std::to_string(i % std::size_t(spec.width)) +
                                           ", " + std::to_string(i / std::size_t(spec.width)) +
                                           ") is not a finite number");
        if (srgbEncoded)
            for (int c = 0; c < 3; ++c) rgba[c] = decodeSrgb(rgba[c]);
    }
    return contents;
}

Result<Image> readImage(const std::filesystem::path& file) {
    auto contents = readImageFile(file);
    if (!contents) return contents.error();
    return std::move(contents->image);
}

Image quantizeAsPng(const Image& image) {
    const std::vector<unsigned char> bytes = encodeSrgb8(image);
    Image quantized(image.width, image.height);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const float stored = float(bytes[i]) / 255.0f;  // what the PNG reader gives
        quantized.rgba[i] = i % 4 == 3 ? stored : decodeSrgb(stored);
    }
    return quantized;
}

namespace {

// Encodes in memory; the one atomic writer puts the bytes on disk.
Status writeWith(const Image& image, const std::filesystem::path& target, FileKind kind) {
    const bool png = kind == FileKind::kPng;
    auto output = OIIO::ImageOutput::create(png ? "png" : "openexr");
    if (!output) return fileError(target, "cannot encode: " + oneLine(OIIO::geterror()));
    OIIO::ImageSpec spec(image.width, image.height, 4,
                         png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.alpha_channel = 3;
    if (png) {
        spec.attribute("oiio:UnassociatedAlpha", 1);
        spec.attribute("oiio:ColorSpace", "sRGB");
    }
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    output->set_ioproxy(&memory);
    bool written = output->open(target.string(), spec);
    if (written) {
        written = png ? output->write_image(OIIO::TypeDesc::UINT8, encodeSrgb8(image).data())
                      : output->write_image(OIIO::TypeDesc::FLOAT, image.rgba.data());
        written = output->close() && written;
    }
    if (!written) return fileError(target, "cannot encode: " + oneLine(output->geterror()));
    return writeFileAtomically(
        target, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

}  // namespace

Status writeImage(const Image& image, const std::filesystem::path& file) {
    const FileKind kind = kindOf(file);
    if (kind != FileKind::kPng && kind != FileKind::kExr)
        return fileError(file, "unsupported image type (expected .png or .exr)");
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != image.pixelCount() * 4)
        return fileError(file, "cannot write an empty or malformed image");
    std::error_code ec;
    const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : ".";
    if (!std::filesystem::is_directory(folder, ec))
        return fileError(file, "cannot write: folder " + displayPath(folder) + " does not exist");
    return writeWith(image, file, kind);
}

}  // namespace matevo
