#include "io/ExrHeaderCheck.h"

#include <cstdint>
#include <cstring>

namespace matevo {
namespace {

constexpr unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr std::uint32_t kMultiPartFlag = 0x1000;
constexpr std::size_t kMaxNameBytes = 256;  // 255 characters with "long names", and the NUL

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
            const std::uint32_t size = readUint32(bytes, at);
            at += 4;
            if (size > bytes.size() - at)
                return Error{"header attribute '" + *name + "' claims " + std::to_string(size) +
                             " bytes, the file has " + std::to_string(bytes.size() - at) + " left"};
            at += size;
        }
        // A multi-part file lists its headers until an empty one.
        if (!multiPart) return Ok{};
        if (at >= bytes.size()) return Error{"the header list ends before its end marker"};
        if (bytes[at] == '\0') return Ok{};
    }
}

}  // namespace matevo
