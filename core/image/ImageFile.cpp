#include "image/ImageFile.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

#include "color/Srgb.h"
#include "common/MemoryBudget.h"
#include "files/AtomicFile.h"
#include "files/InputFile.h"
#include "image/ExrHeaderCheck.h"
#include "image/ImageLibrary.h"
#include "image/ImageType.h"
#include "image/PngCodec.h"

namespace matevo {
namespace {

std::vector<unsigned char> encode8(const Image& image, PngValues values) {
    std::vector<unsigned char> bytes(image.rgba.size());
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        double value = std::clamp(double(image.rgba[i]), 0.0, 1.0);
        // Alpha is coverage, not light.
        if (i % 4 != 3 && values == PngValues::Srgb) value = linearToSrgb(value);
        bytes[i] = static_cast<unsigned char>(std::lround(value * 255.0));
    }
    return bytes;
}

float decodeSrgb(float encoded) { return float(srgbToLinear(encoded)); }

Error fileError(const std::filesystem::path& file, const std::string& what) {
    return badInput(displayPath(file) + ": " + what);
}

// Colour and alpha of one stored sample as linear values in memory: integer samples are
// sRGB-encoded colour (alpha is coverage, never encoded), float samples are linear already.
struct SampleDecoder {
    const std::array<float, 256>& srgb8 = srgb8Table();

    float colour(std::uint8_t sample) const { return srgb8[sample]; }
    float colour(std::uint16_t sample) const { return decodeSrgb(float(sample) / 65535.0f); }
    float colour(float sample) const { return sample; }
    float alpha(std::uint8_t sample) const { return float(sample) / 255.0f; }
    float alpha(std::uint16_t sample) const { return float(sample) / 65535.0f; }
    float alpha(float sample) const { return sample; }

    static const std::array<float, 256>& srgb8Table() {
        static const std::array<float, 256> table = [] {
            std::array<float, 256> values{};
            for (int i = 0; i < 256; ++i) values[i] = decodeSrgb(float(i) / 255.0f);
            return values;
        }();
        return table;
    }
};

// Maps interleaved file pixels of 1-4 channels onto RGBA; grey is replicated, no alpha is 1.
template <typename Sample>
Result<Image> toLinearRgba(const std::vector<Sample>& samples, const DecodedImage& decoded,
                           const std::filesystem::path& file) {
    const SampleDecoder decoder;
    const int channels = decoded.channels;
    const bool hasAlpha = channels == 2 || channels == 4;
    const int colourChannels = hasAlpha ? channels - 1 : channels;
    Image image(decoded.width, decoded.height);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const Sample* source = &samples[i * std::size_t(channels)];
        float* rgba = &image.rgba[i * 4];
        for (int c = 0; c < 3; ++c) rgba[c] = decoder.colour(source[colourChannels == 1 ? 0 : c]);
        rgba[3] = hasAlpha ? decoder.alpha(source[channels - 1]) : 1.0f;
        if constexpr (std::is_same_v<Sample, float>) {
            for (int c = 0; c < 4; ++c)
                if (!std::isfinite(rgba[c]))
                    return fileError(
                        file, "pixel (" + std::to_string(i % std::size_t(decoded.width)) + ", " +
                                  std::to_string(i / std::size_t(decoded.width)) +
                                  ") is not a finite number");
        }
    }
    return image;
}

}  // namespace

Result<ImageFileContents> readImageFile(const std::filesystem::path& file) {
    // Read through the one safe reader (regular files of bounded size only); the decoders then
    // work from memory, so they never open the path themselves.
    auto bytes = readInputFile(file, kMaxImageFileBytes);
    if (!bytes) return bytes.error();
    return decodeImageFile(*bytes, file);
}

Result<ImageFileContents> decodeImageFile(std::string_view bytes,
                                          const std::filesystem::path& file) {
    // The decoded samples plus the RGBA image: checked before anything is allocated.
    const DecodedSizeCheck checkSize = [](int width, int height, int channels) -> Status {
        if (channels < 1 || channels > 4)
            return badInput("unsupported channel count " + std::to_string(channels));
        if (width <= 0 || height <= 0) return badInput("empty image");
        const std::uint64_t pixelCount = std::uint64_t(width) * std::uint64_t(height);
        return checkMemoryEstimate(
            pixelCount * (std::uint64_t(channels) + 4) * sizeof(float),
            "decoding " + std::to_string(width) + "x" + std::to_string(height) + " pixels");
    };
    const std::string extension = lowerCaseExtension(file);
    if (extension == ".exr")
        if (auto headers = checkExrHeaders(bytes); !headers)
            return fileError(file, "not a readable OpenEXR image: " + headers.error().message);
    auto decoded = extension == ".png" ? decodePng(bytes, checkSize)
                                       : decodeWithImageLibrary(bytes, file, checkSize);
    if (!decoded) return fileError(file, decoded.error().message);

    const bool hasAlpha = decoded->channels == 2 || decoded->channels == 4;
    auto image =
        std::visit([&](const auto& samples) { return toLinearRgba(samples, *decoded, file); },
                   decoded->samples);
    if (!image) return image.error();
    return ImageFileContents{std::move(*image), hasAlpha};
}

Result<Image> readImage(const std::filesystem::path& file) {
    auto contents = readImageFile(file);
    if (!contents) return contents.error();
    return std::move(contents->image);
}

Image quantizeAsPng(const Image& image) {
    const std::vector<unsigned char> bytes = encode8(image, PngValues::Srgb);
    Image quantized(image.width, image.height);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const float stored = float(bytes[i]) / 255.0f;  // what the PNG reader gives
        quantized.rgba[i] = i % 4 == 3 ? stored : decodeSrgb(stored);
    }
    return quantized;
}

bool isWritableImageType(const std::filesystem::path& file) {
    const std::string extension = lowerCaseExtension(file);
    return extension == ".png" || extension == ".exr";
}

Status checkImageEncoder(const std::filesystem::path& file) {
    if (!isWritableImageType(file))
        return fileError(file, "unsupported image type to write (expected .png or .exr)");
    if (lowerCaseExtension(file) == ".png") return Ok{};
    return imageLibraryAvailable();
}

Result<std::vector<unsigned char>> encodePng(const Image& image, PngValues values) {
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != image.pixelCount() * 4)
        return internalError("cannot encode an empty or malformed image as PNG");
    auto encoded =
        encodePngRgba8(encode8(image, values).data(), image.width, image.height,
                       values == PngValues::Srgb ? PngEncodingTag::Srgb : PngEncodingTag::Linear);
    if (!encoded) return withContext(encoded.error(), "cannot encode PNG");
    return std::vector<unsigned char>(encoded->begin(), encoded->end());
}

Status writeImage(const Image& image, const std::filesystem::path& file) {
    if (!isWritableImageType(file))
        return fileError(file, "unsupported image type to write (expected .png or .exr)");
    const std::string extension = lowerCaseExtension(file);
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != image.pixelCount() * 4)
        return fileError(file, "cannot write an empty or malformed image");
    std::error_code ec;
    const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : ".";
    if (!std::filesystem::is_directory(folder, ec))
        return fileError(file, "cannot write: folder " + displayPath(folder) + " does not exist");
    // Encoded in memory; the one atomic writer puts the bytes on disk.
    auto encoded =
        extension == ".png"
            ? encodePngRgba8(encode8(image, PngValues::Srgb).data(), image.width, image.height)
            : encodeExrWithImageLibrary(image.rgba.data(), image.width, image.height);
    if (!encoded) return fileError(file, "cannot encode: " + encoded.error().message);
    return writeFileAtomically(file, *encoded);
}

}  // namespace matevo
