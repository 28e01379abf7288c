#pragma once
// A set of variants on disk, as `matevo variants --out DIR` writes it (DIR/variants/
// variant_NNN.json) or any folder of genome JSON files (the form `render --genome` reads):
// every *.json file, in name order. Errors name the file and field.
#include <filesystem>
#include <vector>

#include "common/Result.h"
#include "genome/Genome.h"

namespace matevo {

struct VariantFile {
    std::filesystem::path file;
    Genome genome;
};

Result<std::vector<VariantFile>> loadVariantFolder(const std::filesystem::path& folder);

}  // namespace matevo
