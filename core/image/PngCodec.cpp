#include "image/PngCodec.h"

#include <png.h>

#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "common/HugePages.h"

namespace matevo {
namespace {

// libpng reports errors by longjmp. Every function that may jump holds only trivially
// destructible locals, so a jump skips no destructor; buffers are owned by the callers.
struct PngMessages {
    char text[256] = "";
};

[[noreturn]] void onPngError(png_structp png, png_const_charp message) {
    auto* messages = static_cast<PngMessages*>(png_get_error_ptr(png));
    std::snprintf(messages->text, sizeof messages->text, "%s", message);
    png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}  // warnings do not stop a read

struct MemorySource {
    const char* data;
    std::size_t size;
    std::size_t offset;
};

void readFromMemory(png_structp png, png_bytep out, png_size_t length) {
    auto* source = static_cast<MemorySource*>(png_get_io_ptr(png));
    if (length > source->size - source->offset) png_error(png, "file is truncated");
    std::memcpy(out, source->data + source->offset, length);
    source->offset += length;
}

// libpng allocates (and fills) each chunk at the length its header claims before reading it,
// and Debian's libpng only warns about a claim past its limit: a 340-byte file claiming a
// 1.9 GB chunk took 1.9 GB and 16 s to refuse. So every chunk up to IEND must fit in the file.
Status checkChunkLengths(std::string_view bytes) {
    constexpr std::size_t kSignatureBytes = 8, kFramingBytes = 12;  // length, type, CRC
    for (std::size_t at = kSignatureBytes; at + kFramingBytes <= bytes.size();) {
        const auto* chunk = reinterpret_cast<const unsigned char*>(bytes.data() + at);
        const std::uint64_t length = std::uint64_t(chunk[0]) << 24 | std::uint64_t(chunk[1]) << 16 |
                                     std::uint64_t(chunk[2]) << 8 | std::uint64_t(chunk[3]);
        if (length > bytes.size() - at - kFramingBytes)
            return badInput("a chunk claims " + std::to_string(length) +
                            " bytes, more than the file holds");
        if (std::memcmp(chunk + 4, "IEND", 4) == 0) break;
        at += kFramingBytes + length;
    }
    return Ok{};  // a file that ends early is libpng's to report
}

struct PngHeader {
    png_uint_32 width = 0;
    png_uint_32 height = 0;
    int channels = 0;
    int bitDepth = 0;
};

// Reads the header and sets the transforms that give samples as DecodedImage describes them.
bool readHeader(png_structp png, png_infop info, PngHeader& header) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    png_set_expand(png);  // palette -> RGB, grey < 8 bits -> 8 bits, tRNS -> alpha
    if (png_get_bit_depth(png, info) == 16) png_set_swap(png);  // to the host's byte order
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    header.width = png_get_image_width(png, info);
    header.height = png_get_image_height(png, info);
    header.channels = png_get_channels(png, info);
    header.bitDepth = png_get_bit_depth(png, info);
    return true;
}

bool readRows(png_structp png, png_infop info, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, info);
    return true;
}

class PngReader {
public:
    PngReader() {
        png_ = png_create_read_struct(PNG_LIBPNG_VER_STRING, &messages_, onPngError, onPngWarning);
        if (png_) info_ = png_create_info_struct(png_);
    }
    ~PngReader() { png_destroy_read_struct(&png_, info_ ? &info_ : nullptr, nullptr); }
    PngReader(const PngReader&) = delete;
    PngReader& operator=(const PngReader&) = delete;

    png_structp png() const { return png_; }
    png_infop info() const { return info_; }
    Error error() const {
        return badInput(std::string("not a readable PNG image: ") + messages_.text);
    }

private:
    PngMessages messages_;
    png_structp png_ = nullptr;
    png_infop info_ = nullptr;
};

template <typename Sample>
Result<DecodedImage> readSamples(PngReader& reader, const PngHeader& header) {
    const std::size_t rowSamples = std::size_t(header.width) * std::size_t(header.channels);
    std::vector<Sample> samples;
    resizeOnHugePages(samples, rowSamples * header.height);
    std::vector<png_bytep> rows(header.height);
    for (std::size_t y = 0; y < rows.size(); ++y)
        rows[y] = reinterpret_cast<png_bytep>(samples.data() + y * rowSamples);
    if (!readRows(reader.png(), reader.info(), rows.data())) return reader.error();
    return DecodedImage{int(header.width), int(header.height), header.channels, std::move(samples)};
}

bool writeAll(png_structp png, png_infop info, const std::uint8_t* rgba, int width, int height,
              PngEncodingTag tag) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGBA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (tag == PngEncodingTag::Srgb)
        png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    else
        png_set_gAMA(png, info, 1.0);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y)
        png_write_row(png, rgba + std::size_t(y) * std::size_t(width) * 4);
    png_write_end(png, info);
    return true;
}

void appendToString(png_structp png, png_bytep data, png_size_t length) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<char*>(data), length);
}

void flushNothing(png_structp) {}

}  // namespace

Result<DecodedImage> decodePng(std::string_view bytes, const DecodedSizeCheck& checkSize) {
    if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8))
        return badInput("not a readable PNG image: no PNG signature");
    if (auto chunks = checkChunkLengths(bytes); !chunks)
        return badInput("not a readable PNG image: " + chunks.error().message);
    PngReader reader;
    if (!reader.info()) return environmentError("out of memory");
    MemorySource source{bytes.data(), bytes.size(), 0};
    png_set_read_fn(reader.png(), &source, readFromMemory);
    PngHeader header;
    if (!readHeader(reader.png(), reader.info(), header)) return reader.error();
    if (auto fits = checkSize(int(header.width), int(header.height), header.channels); !fits)
        return fits.error();
    return header.bitDepth == 16 ? readSamples<std::uint16_t>(reader, header)
                                 : readSamples<std::uint8_t>(reader, header);
}

Result<std::string> encodePngRgba8(const std::uint8_t* rgba, int width, int height,
                                   PngEncodingTag tag) {
    PngMessages messages;
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &messages, onPngError, onPngWarning);
    if (!png) return environmentError("out of memory");
    png_infop info = png_create_info_struct(png);
    std::string encoded;
    png_set_write_fn(png, &encoded, appendToString, flushNothing);
    const bool written = info && writeAll(png, info, rgba, width, height, tag);
    png_destroy_write_struct(&png, info ? &info : nullptr);
    // Encoding into memory fails only for want of memory or by a bug.
    if (!written) return info ? internalError(messages.text) : environmentError("out of memory");
    return encoded;
}

}  // namespace matevo
