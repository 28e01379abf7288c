#include "PresetOption.h"

#include "Messages.h"
#include "Suggestion.h"
#include "documents/PresetCatalog.h"
#include "files/ResourcePaths.h"

namespace matevo::cli {

std::filesystem::path resolvePreset(const std::string& pathOrName) {
    if (looksLikePresetPath(pathOrName)) return pathOrName;
    auto presets = listPresets();
    if (!presets) throw CommandFailure(presets.error());
    std::vector<std::string> names;
    for (const PresetEntry& entry : *presets) {
        if (entry.name == pathOrName) return entry.file;
        names.push_back(entry.name);
    }
    std::string folders = userPresetDirectory().string();
    if (auto shipped = findResourceDirectory("presets"))
        folders += (folders.empty() ? "" : " or ") + shipped->string();
    throw UsageError("no preset named '" + pathOrName + "' in " + folders +
                     didYouMean(pathOrName, names) + "; matevo presets lists them");
}

PresetChoice loadPresetFile(const std::filesystem::path& file) {
    auto loaded = loadPreset(file);
    if (!loaded) throw CommandFailure(loaded.error());
    for (const auto& warning : loaded->warnings) printWarning(warning);
    return {std::move(loaded->preset), file};
}

PresetChoice loadDefaultPreset() {
    auto defaultFile = defaultPresetPath();
    if (!defaultFile) throw CommandFailure(defaultFile.error());
    return loadPresetFile(*defaultFile);
}

PresetChoice loadPresetOption(CommandLine& args) {
    if (auto preset = args.option("--preset")) {
        PresetChoice choice = loadPresetFile(resolvePreset(*preset));
        choice.named = true;
        return choice;
    }
    return loadDefaultPreset();
}

}  // namespace matevo::cli
