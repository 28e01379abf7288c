#pragma once
// The table of functions the OpenImageIO module (module/OiioImageLibrary.cpp) exports to
// ImageLibrary. Module and executable are built together, from the same sources and compiler,
// so C++ types may cross; the version guards against a module left from another build.
#include <filesystem>
#include <string>
#include <string_view>

#include "common/Result.h"
#include "image/DecodedImage.h"

namespace matevo {

constexpr int kImageLibraryAbiVersion = 1;

struct ImageLibraryFunctions {
    int abiVersion;
    // Any format OpenImageIO reads, chosen by the file's extension (any case). The bytes are
    // decoded from memory; `file` is opened directly only for a format OpenImageIO cannot
    // decode from memory. Errors are one line and do not name the file.
    Result<DecodedImage> (*decode)(std::string_view bytes, const std::filesystem::path& file,
                                   const DecodedSizeCheck& checkSize);
    // Linear RGBA (straight alpha) as a 32-bit float OpenEXR file.
    Result<std::string> (*encodeExr)(const float* rgba, int width, int height);
};

}  // namespace matevo

// The one symbol the module exports.
extern "C" const matevo::ImageLibraryFunctions* matevoImageLibrary();
