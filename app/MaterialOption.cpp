#include "MaterialOption.h"

#include "Messages.h"

namespace matevo::cli {

MaterialSource::MaterialSource(CommandLine& args) : preset_(loadPresetOption(args)) {}

MaterialFile MaterialSource::presetMaterial() const {
    return materialFromPreset(preset_.preset, preset_.file, preset_.preset.target,
                              preset_.preset.name);
}

MaterialFile MaterialSource::load(const std::filesystem::path& file) const {
    auto loaded = loadMaterial(file, presetMaterial());
    if (!loaded) throw UsageError(loaded.error().message);
    if (preset_.named && !loaded->fromContext)
        throw UsageError("--preset: not used: " + file.string() +
                         " names its own family, kappa, textures and scene");
    for (const auto& warning : loaded->warnings) printWarning(warning);
    return std::move(loaded->file);
}

}  // namespace matevo::cli
