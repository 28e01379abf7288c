#include "io/ExrHeaderCheck.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <utility>

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
        return Error{std::string("header ") + what + " is not terminated"};
    std::string name(bytes.substr(at, end - at));
    at = end + 1;
    return name;
}

Error overrun(const std::string& name, std::uint64_t claimed, std::size_t left) {
    return Error{"header attribute '" + name + "' claims " + std::to_string(claimed) +
                 " bytes, the file has " + std::to_string(left) + " left"};
}

// Advances `at` past the value of attribute `name` of `type` as OpenEXR reads it, refusing any
// value (or any part OpenEXR allocates for) that reaches past the end of the file.
Status skipValue(std::string_view bytes, std::size_t& at, const std::string& name,
                 const std::string& type, std::uint32_t declared) {
    const std::size_t left = bytes.size() - at;
    for (const auto& [fixedType, size] : kFixedSizeTypes) {
        if (type != fixedType) continue;
        if (type == "chlist") {
            while (true) {
                auto channel = readName(bytes, at, "channel name");
                if (!channel) return channel.error();
                if (channel->empty()) return Ok{};
                if (bytes.size() - at < kChannelBytes)
                    return Error{"header channel '" + *channel + "' is cut short"};
                at += kChannelBytes;
            }
        }
        if (size > left) return overrun(name, size, left);
        std::uint64_t total = size;
        if (type == "preview")
            total += std::uint64_t(readUint32(bytes, at)) * readUint32(bytes, at + 4) * 4;
        if (total > left) return overrun(name, total, left);
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
        while (true) {
            if (at >= bytes.size()) return Error{"the header ends before its end marker"};
            if (bytes[at] == '\0') {
                ++at;
                break;
            }
            auto name = readName(bytes, at, "attribute name");
            if (!name) return name.error();
            auto type = readName(bytes, at, "attribute type");
            if (!type) return type.error();
            if (bytes.size() - at < 4) return Error{"header attribute '" + *name + "' has no size"};
            const std::uint32_t declared = readUint32(bytes, at);
            at += 4;
            if (auto skipped = skipValue(bytes, at, *name, *type, declared); !skipped)
                return skipped;
        }
        // A multi-part file lists its headers until an empty one.
        if (!multiPart) return Ok{};
        if (at >= bytes.size()) return Error{"the header list ends before its end marker"};
        if (bytes[at] == '\0') return Ok{};
    }
}

}  // namespace matevo
