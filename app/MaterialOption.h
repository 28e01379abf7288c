#pragma once
// Material JSON files for the commands that read them (render --genome, export): any JSON that
// matevo writes for a material (documents/MaterialFile.h). A bare genome carries no family, so it
// takes the family, kappa, textures and scene of --preset (or the default preset); beside a file
// that names its own, --preset would do nothing and is refused. The preset is read only when it is
// needed, so that material files (a moved variant set) are read where no preset can be found.
// Warnings go to stderr; errors become a UsageError (exit 2).
#include <filesystem>
#include <optional>
#include <string>

#include "CommandLine.h"
#include "PresetOption.h"
#include "documents/MaterialFile.h"

namespace matevo::cli {

class MaterialSource {
public:
    // Consumes --preset (read when first needed).
    explicit MaterialSource(CommandLine& args);

    // The preset's target as a material.
    MaterialFile presetMaterial() const;
    MaterialFile load(const std::filesystem::path& file) const;

private:
    const PresetChoice& preset() const;

    std::optional<std::string> presetOption_;
    mutable std::optional<PresetChoice> preset_;
};

}  // namespace matevo::cli
