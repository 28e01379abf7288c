#include "documents/PresetCatalog.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <system_error>

#include "files/ResourcePaths.h"
#include "files/XdgFolders.h"

namespace matevo {
namespace {

bool hasJsonExtension(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension == ".json";
}

// Adds the folder's NAME.json files to the map unless a name is already there.
void addPresetsIn(const std::filesystem::path& folder, bool shipped,
                  std::map<std::string, PresetEntry>& byName) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        if (!entry.is_regular_file(error) || !hasJsonExtension(entry.path())) continue;
        const std::string name = entry.path().stem().string();
        byName.try_emplace(name, PresetEntry{name, entry.path(), shipped});
    }
}

}  // namespace

std::filesystem::path userPresetDirectory() {
    const std::filesystem::path dataHome = xdgHome(XdgHome::Data);
    return dataHome.empty() ? dataHome : dataHome / "matevo" / "presets";
}

bool looksLikePresetPath(std::string_view text) {
    return text.find('/') != std::string_view::npos ||
           hasJsonExtension(std::filesystem::path(text));
}

Result<std::vector<PresetEntry>> listPresets() {
    auto shipped = findResourceDirectory("presets");
    if (!shipped) return shipped.error();
    std::map<std::string, PresetEntry> byName;
    if (const auto user = userPresetDirectory(); !user.empty()) addPresetsIn(user, false, byName);
    addPresetsIn(*shipped, true, byName);
    std::vector<PresetEntry> presets;
    for (auto& [name, entry] : byName) presets.push_back(std::move(entry));
    return presets;
}

}  // namespace matevo
