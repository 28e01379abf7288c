#include "PresetOption.h"

#include <cstdio>

#include "io/ResourcePaths.h"

namespace matevo::cli {

PresetChoice loadPresetFile(const std::filesystem::path& file) {
    auto loaded = loadPreset(file);
    if (!loaded) throw UsageError(loaded.error().message);
    for (const auto& warning : loaded->warnings)
        std::fprintf(stderr, "matevo: warning: %s\n", warning.c_str());
    return {std::move(loaded->preset), file};
}

PresetChoice loadPresetOption(CommandLine& args) {
    if (auto file = args.option("--preset")) {
        PresetChoice choice = loadPresetFile(*file);
        choice.named = true;
        return choice;
    }
    auto defaultFile = defaultPresetPath();
    if (!defaultFile) throw std::runtime_error(defaultFile.error().message);
    return loadPresetFile(*defaultFile);
}

}  // namespace matevo::cli
