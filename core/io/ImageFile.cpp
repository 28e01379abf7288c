#include "io/ImageFile.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cmath>
#include <string>
#include <system_error>
#include <vector>

#include "color/Srgb.h"

namespace matevo {
namespace {

enum class FileKind { kPng, kExr, kUnsupported };

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
    return FileKind::kUnsupported;
}

// OpenImageIO messages may span lines; our errors are one line.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text.empty() ? std::string("unknown OpenImageIO error") : text;
}

Error fileError(const std::filesystem::path& file, const std::string& what) {
    return Error{file.string() + ": " + what};
}

// Maps an interleaved file pixel of 1-4 channels onto RGBA; grey is replicated.
void expandToRgba(const float* source, int channels, bool hasAlpha, float* rgba) {
    const int colourChannels = hasAlpha ? channels - 1 : channels;
    for (int c = 0; c < 3; ++c) rgba[c] = source[colourChannels == 1 ? 0 : c];
    rgba[3] = hasAlpha ? source[channels - 1] : 1.0f;
}

}  // namespace

Result<ImageFileContents> readImageFile(const std::filesystem::path& file) {
    const FileKind kind = kindOf(file);
    if (kind == FileKind::kUnsupported)
        return fileError(file, "unsupported image type (expected .png or .exr)");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        return fileError(file, "cannot read: no such file");

    // PNG stores straight alpha; without this hint OpenImageIO would premultiply on read.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto input = OIIO::ImageInput::open(file.string(), &config);
    if (!input) return fileError(file, "not a readable image: " + oneLine(OIIO::geterror()));
    const std::string expectedFormat = kind == FileKind::kPng ? "png" : "openexr";
    if (input->format_name() != expectedFormat)
        return fileError(file, std::string("contents are ") + input->format_name() +
                                   ", not what the extension says");

    const OIIO::ImageSpec& spec = input->spec();
    const int channels = spec.nchannels;
    if (channels < 1 || channels > 4)
        return fileError(file, "unsupported channel count " + std::to_string(channels));
    if (spec.width <= 0 || spec.height <= 0) return fileError(file, "empty image");
    const bool hasAlpha = channels == 2 || channels == 4;

    std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) *
                              std::size_t(channels));
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        return fileError(file, "cannot decode: " + oneLine(input->geterror()));

    ImageFileContents contents{Image(spec.width, spec.height), hasAlpha};
    const bool srgbEncoded = kind == FileKind::kPng;
    for (std::size_t i = 0; i < contents.image.pixelCount(); ++i) {
        float* rgba = &contents.image.rgba[i * 4];
        expandToRgba(&pixels[i * std::size_t(channels)], channels, hasAlpha, rgba);
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

// Unique per process and call, so concurrent writers never share a temporary file.
std::filesystem::path temporaryPathBeside(const std::filesystem::path& file) {
    static std::atomic<unsigned> counter{0};
    std::filesystem::path temporary = file;
    temporary += ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    return temporary;
}

Status writeWith(const Image& image, const std::filesystem::path& target, FileKind kind) {
    const bool png = kind == FileKind::kPng;
    auto output = OIIO::ImageOutput::create(png ? "png" : "openexr");
    if (!output) return fileError(target, "cannot write: " + oneLine(OIIO::geterror()));
    OIIO::ImageSpec spec(image.width, image.height, 4,
                         png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.alpha_channel = 3;
    if (png) {
        spec.attribute("oiio:UnassociatedAlpha", 1);
        spec.attribute("oiio:ColorSpace", "sRGB");
    }
    const std::filesystem::path temporary = temporaryPathBeside(target);
    bool written = output->open(temporary.string(), spec);
    if (written) {
        written = png ? output->write_image(OIIO::TypeDesc::UINT8, encodeSrgb8(image).data())
                      : output->write_image(OIIO::TypeDesc::FLOAT, image.rgba.data());
        written = output->close() && written;
    }
    std::error_code ec;
    if (!written) {
        std::filesystem::remove(temporary, ec);
        return fileError(target, "cannot write: " + oneLine(output->geterror()));
    }
    std::filesystem::rename(temporary, target, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        return fileError(target, "cannot write: " + ec.message());
    }
    return Ok{};
}

}  // namespace

Status writeImage(const Image& image, const std::filesystem::path& file) {
    const FileKind kind = kindOf(file);
    if (kind == FileKind::kUnsupported)
        return fileError(file, "unsupported image type (expected .png or .exr)");
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != image.pixelCount() * 4)
        return fileError(file, "cannot write an empty or malformed image");
    std::error_code ec;
    const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : ".";
    if (!std::filesystem::is_directory(folder, ec))
        return fileError(file, "cannot write: folder " + folder.string() + " does not exist");
    return writeWith(image, file, kind);
}

}  // namespace matevo
