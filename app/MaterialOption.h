#pragma once
// Material JSON files for the commands that read them (render --genome, export): any JSON that
// matevo writes for a material (io/MaterialFile.h). A bare genome carries no family, so it takes
// the family, kappa, textures and scene of --preset (or the default preset); beside a file that
// names its own, --preset would do nothing and is refused. Warnings go to stderr; errors become
// a UsageError (exit 2).
#include <filesystem>

#include "CommandLine.h"
#include "PresetOption.h"
#include "io/MaterialFile.h"

namespace matevo::cli {

class MaterialSource {
public:
    // Consumes --preset.
    explicit MaterialSource(CommandLine& args);

    // The preset's target as a material.
    MaterialFile presetMaterial() const;
    MaterialFile load(const std::filesystem::path& file) const;

private:
    PresetChoice preset_;
};

}  // namespace matevo::cli
