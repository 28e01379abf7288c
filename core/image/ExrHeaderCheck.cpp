#include "image/ExrHeaderCheck.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <utility>

#include "common/MemoryBudget.h"

namespace matevo {
namespace {

constexpr unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr std::uint32_t kMultiPartFlag = 0x1000;
constexpr std::size_t kMaxNameBytes = 256;  // 255 characters with "long names", and the NUL
constexpr std::size_t kChannelBytes = 16;   // pixel type, pLinear and reserved, two samplings

// OpenEXR reads these types by their own size, whatever size the file declares, and then goes
// on reading the next attribute from where it stopped; so must we.
constexpr std::array<std::pair<const char*, std::size_t>, 26> kFixedSizeTypes{{
    {"box2i", 16},
    {"box2f", 16},
    {"chromaticities", 32},
    {"compression", 1},
    {"envmap", 1},
    {"lineOrder", 1},
    {"deepImageState", 1},
    {"double", 8},
    {"float", 4},
    {"int", 4},
    {"rational", 8},
    {"timecode", 8},
    {"keycode", 28},
    {"m33f", 36},
    {"m33d", 72},
    {"m44f", 64},
    {"m44d", 128},
    {"tiledesc", 9},
    {"v2i", 8},
    {"v2f", 8},
    {"v2d", 16},
    {"v3i", 12},
    {"v3f", 12},
    {"v3d", 24},
    {"preview", 8},  // plus width x height x 4 bytes, checked below
    {"chlist", 0},   // channels until an empty name, walked below
}};

// What OpenEXR sizes its block buffers by, from one header.
struct BlockLayout {
    std::int64_t width = 0;                      // of the data window
    int compression = 0;                         // OpenEXR's Compression enum
    std::int64_t tileWidth = 0, tileHeight = 0;  // 0 for scan-line files
    std::uint64_t bytesPerPixel = 0;             // summed over the channels
};

// Rows per compressed block of a scan-line file: NONE, RLE, ZIPS, ZIP, PIZ, PXR24, B44, B44A,
// DWAA, DWAB; an unknown method is refused by OpenEXR itself.
std::int64_t rowsPerBlock(int compression) {
    constexpr std::int64_t kRows[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
    return compression >= 0 && compression < 10 ? kRows[compression] : 1;
}

// OpenEXR allocates a block's uncompressed and compressed buffers when it opens the file,
// before any pixel is read, whatever the image's height: a file of a few hundred bytes
// claiming a data window a million pixels wide would make it allocate hundreds of MiB.
Status checkBlockMemory(const BlockLayout& layout) {
    const bool tiled = layout.tileWidth > 0 && layout.tileHeight > 0;
    const std::int64_t width = tiled ? layout.tileWidth : layout.width;
    const std::int64_t rows = tiled ? layout.tileHeight : rowsPerBlock(layout.compression);
    if (width <= 0 || rows <= 0) return Ok{};
    const std::uint64_t bytes = std::uint64_t(width) * std::uint64_t(rows) *
                                std::max<std::uint64_t>(layout.bytesPerPixel, 1) * 2;
    return checkMemoryEstimate(
        bytes, "its blocks of " + std::to_string(width) + "x" + std::to_string(rows) + " pixels");
}

std::uint32_t readUint32(std::string_view bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i)
        value = (value << 8) | static_cast<unsigned char>(bytes[at + std::size_t(i)]);
    return value;
}

// A NUL-terminated name starting at `at`; advances `at` past the NUL.
Result<std::string> readName(std::string_view bytes, std::size_t& at, const char* what) {
    const std::size_t end = bytes.find('\0', at);
    if (end == std::string_view::npos || end - at >= kMaxNameBytes)
        return badInput(std::string("header ") + what + " is not terminated");
    std::string name(bytes.substr(at, end - at));
    at = end + 1;
    return name;
}

Error overrun(const std::string& name, std::uint64_t claimed, std::size_t left) {
    return badInput("header attribute '" + name + "' claims " + std::to_string(claimed) +
                    " bytes, the file has " + std::to_string(left) + " left");
}

// Advances `at` past the value of attribute `name` of `type` as OpenEXR reads it, refusing any
// value (or any part OpenEXR allocates for) that reaches past the end of the file.
Status skipValue(std::string_view bytes, std::size_t& at, const std::string& name,
                 const std::string& type, std::uint32_t declared, BlockLayout& layout) {
    const std::size_t left = bytes.size() - at;
    for (const auto& [fixedType, size] : kFixedSizeTypes) {
        if (type != fixedType) continue;
        if (type == "chlist") {
            while (true) {
                auto channel = readName(bytes, at, "channel name");
                if (!channel) return channel.error();
                if (channel->empty()) return Ok{};
                if (bytes.size() - at < kChannelBytes)
                    return badInput("header channel '" + *channel + "' is cut short");
                if (name == "channels")  // UINT and FLOAT samples take 4 bytes, HALF 2
                    layout.bytesPerPixel += readUint32(bytes, at) == 1 ? 2 : 4;
                at += kChannelBytes;
            }
        }
        if (size > left) return overrun(name, size, left);
        std::uint64_t total = size;
        if (type == "preview")
            total += std::uint64_t(readUint32(bytes, at)) * readUint32(bytes, at + 4) * 4;
        if (total > left) return overrun(name, total, left);
        const auto signedAt = [&](std::size_t offset) {
            return std::int64_t(std::int32_t(readUint32(bytes, at + offset)));
        };
        if (name == "dataWindow" && type == "box2i") {
            layout.width = signedAt(8) - signedAt(0) + 1;
        } else if (name == "compression") {
            layout.compression = static_cast<unsigned char>(bytes[at]);
        } else if (name == "tiles" && type == "tiledesc") {
            layout.tileWidth = std::int64_t(readUint32(bytes, at));
            layout.tileHeight = std::int64_t(readUint32(bytes, at + 4));
        }
        at += std::size_t(total);
        return Ok{};
    }
    if (declared > left) return overrun(name, declared, left);
    if (type == "stringvector")  // each string's own length must fit in the declared size
        for (std::size_t read = 0; read + 4 <= declared;) {
            const std::uint32_t length = readUint32(bytes, at + read);
            read += 4;
            if (length > declared - read) return overrun(name, length, declared - read);
            read += length;
        }
    at += declared;
    return Ok{};
}

}  // namespace

Status checkExrHeaders(std::string_view bytes) {
    if (bytes.size() < 8 || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) return Ok{};
    const bool multiPart = (readUint32(bytes, 4) & kMultiPartFlag) != 0;
    std::size_t at = 8;
    while (true) {
        // One header: attributes until a NUL byte.
        BlockLayout layout;
        while (true) {
            if (at >= bytes.size()) return badInput("the header ends before its end marker");
            if (bytes[at] == '\0') {
                ++at;
                break;
            }
            auto name = readName(bytes, at, "attribute name");
            if (!name) return name.error();
            auto type = readName(bytes, at, "attribute type");
            if (!type) return type.error();
            if (bytes.size() - at < 4)
                return badInput("header attribute '" + *name + "' has no size");
            const std::uint32_t declared = readUint32(bytes, at);
            at += 4;
            if (auto skipped = skipValue(bytes, at, *name, *type, declared, layout); !skipped)
                return skipped;
        }
        if (auto fits = checkBlockMemory(layout); !fits) return fits;
        // A multi-part file lists its headers until an empty one.
        if (!multiPart) return Ok{};
        if (at >= bytes.size()) return badInput("the header list ends before its end marker");
        if (bytes[at] == '\0') return Ok{};
    }
}

}  // namespace matevo
