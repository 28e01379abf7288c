#pragma once
// A set of variants on disk, as `matevo variants --out DIR` writes it (DIR/variants/
// variant_NNN.json) or any folder of material JSON files (what `render --genome` reads): every
// *.json file, in name order, read as a material (io/MaterialFile.h), so that each keeps its own
// kappa (hue variety); a bare genome takes `context`'s family, kappa, textures and scene.
// Errors name the file and field.
#include <filesystem>
#include <string>
#include <vector>

#include "common/Result.h"
#include "io/MaterialFile.h"

namespace matevo {

struct VariantFile {
    std::filesystem::path file;
    MaterialFile material;
    std::vector<std::string> warnings;  // each naming the file and field
};

Result<std::vector<VariantFile>> loadVariantFolder(const std::filesystem::path& folder,
                                                   const MaterialFile& context);

}  // namespace matevo
