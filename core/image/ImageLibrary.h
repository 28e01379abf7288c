#pragma once
// OpenImageIO, loaded only when a command needs an image format other than PNG: it maps
// hundreds of shared libraries, which would cost every command a quarter of a second to start.
// The module is looked for beside the executable (BUILD/lib/matevo, as CMake builds it) and in
// the install prefix (PREFIX/lib/matevo for PREFIX/bin/matevo).
#include <filesystem>
#include <string>
#include <string_view>

#include "common/Result.h"
#include "image/DecodedImage.h"

namespace matevo {

// Whether the module loads; the error says where it was looked for, or why it would not load.
Status imageLibraryAvailable();

// The functions of image/ImageLibraryAbi.h; errors say why the module could not be loaded.
Result<DecodedImage> decodeWithImageLibrary(std::string_view bytes,
                                            const std::filesystem::path& file,
                                            const DecodedSizeCheck& checkSize);
Result<std::string> encodeExrWithImageLibrary(const float* rgba, int width, int height);

}  // namespace matevo
