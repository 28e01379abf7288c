#include "MaterialOption.h"

#include "Messages.h"

namespace matevo::cli {

MaterialSource::MaterialSource(CommandLine& args) : presetOption_(args.option("--preset")) {}

const PresetChoice& MaterialSource::preset() const {
    if (!preset_) {
        preset_ =
            presetOption_ ? loadPresetFile(resolvePreset(*presetOption_)) : loadDefaultPreset();
        preset_->named = presetOption_.has_value();
    }
    return *preset_;
}

MaterialFile MaterialSource::presetMaterial() const {
    return materialFromPreset(preset().preset, preset().file, preset().preset.target,
                              preset().preset.name);
}

MaterialFile MaterialSource::load(const std::filesystem::path& file) const {
    // A material file names everything itself; only a bare genome (or a file that fails on its
    // own) is read again in the preset's context.
    auto loaded = loadMaterial(file, MaterialFile{});
    if (!loaded || loaded->fromContext) loaded = loadMaterial(file, presetMaterial());
    if (!loaded) throw CommandFailure(loaded.error());
    if (presetOption_ && !loaded->fromContext)
        throw UsageError("--preset: not used: " + file.string() +
                         " names its own family, kappa, textures and scene");
    for (const auto& warning : loaded->warnings) printWarning(warning);
    return std::move(loaded->file);
}

}  // namespace matevo::cli
