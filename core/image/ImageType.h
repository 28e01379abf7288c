#pragma once
// An image file's type is its extension, in any case: "a.PNG" is a PNG file.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace matevo {

// ".png" for "a.PNG"; empty when the name has no extension.
inline std::string lowerCaseExtension(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

}  // namespace matevo
