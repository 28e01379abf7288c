#pragma once
// A set of variants on disk, as `matevo variants --out DIR` writes it (DIR/variants/
// variant_NNN.json) or any folder of material JSON files (what `render --genome` reads): every
// *.json file, in name order, read as a material (documents/MaterialFile.h), so that each keeps its
// own kappa (hue variety); a bare genome takes `context`'s family, kappa, textures and scene. Other
// files are passed over. The one way a set is enumerated: `scene --variants` and `export
// --variants` read the same members. Errors name the file and field.
#include <filesystem>
#include <string>
#include <vector>

#include "common/Result.h"
#include "documents/MaterialFile.h"

namespace matevo {

struct VariantFile {
    std::filesystem::path file;
    MaterialFile material;
    std::vector<std::string> warnings;  // each naming the file and field
};

// The set's material files in name order: DIR/variants/*.json when DIR has a variants folder,
// else DIR/*.json; an error when there is none.
Result<std::vector<std::filesystem::path>> variantFolderFiles(const std::filesystem::path& folder);

// Those files read as materials.
Result<std::vector<VariantFile>> loadVariantFolder(const std::filesystem::path& folder,
                                                   const MaterialFile& context);

}  // namespace matevo
