#pragma once
// Reading back what a test wrote: a file's bytes, a folder's entry names.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

namespace matevo::testing {

inline std::string contentsOf(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline std::set<std::string> namesIn(const std::filesystem::path& folder) {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        names.insert(entry.path().filename().string());
    return names;
}

}  // namespace matevo::testing
