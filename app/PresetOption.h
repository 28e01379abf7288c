#pragma once
// The --preset option shared by subcommands: a preset file, or a preset by name (`matevo
// presets` lists them), or the built-in default (validation metal) when absent. Warnings go to
// stderr; errors become a UsageError (exit 2).
#include <filesystem>
#include <string>

#include "CommandLine.h"
#include "documents/Preset.h"

namespace matevo::cli {

struct PresetChoice {
    Preset preset;
    std::filesystem::path file;  // textures are relative to its folder
    bool named = false;          // given with --preset, not the default
};

// A path ("dir/x.json", "x.json") is taken as it is; anything else is a preset name, looked up
// in the user's and the shipped preset folders (documents/PresetCatalog.h).
std::filesystem::path resolvePreset(const std::string& pathOrName);

PresetChoice loadPresetOption(CommandLine& args);
PresetChoice loadPresetFile(const std::filesystem::path& file);
PresetChoice loadDefaultPreset();

}  // namespace matevo::cli
