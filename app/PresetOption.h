#pragma once
// The --preset option shared by subcommands: loads the named preset, or the built-in default
// (validation metal) when absent. Warnings go to stderr; errors become a UsageError (exit 2).
#include <filesystem>

#include "CommandLine.h"
#include "io/Preset.h"

namespace matevo::cli {

struct PresetChoice {
    Preset preset;
    std::filesystem::path file;  // textures are relative to its folder
    bool named = false;          // given with --preset, not the default
};

PresetChoice loadPresetOption(CommandLine& args);
PresetChoice loadPresetFile(const std::filesystem::path& file);

}  // namespace matevo::cli
