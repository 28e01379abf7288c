#include "documents/VariantFolder.h"

#include <algorithm>

namespace matevo {

Result<std::vector<std::filesystem::path>> variantFolderFiles(const std::filesystem::path& folder) {
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        return badInput(folder.string() + ": not a folder of variants");
    // `matevo variants --out DIR` puts the material files one level down.
    const std::filesystem::path variants =
        std::filesystem::is_directory(folder / "variants", error) ? folder / "variants" : folder;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(variants, error)) {
        // An entry whose type cannot be read (a symlink loop) is kept, for its loader to refuse
        // with the reason.
        std::error_code typeError;
        if (entry.path().extension() == ".json" && (entry.is_regular_file(typeError) || typeError))
            files.push_back(entry.path());
    }
    if (error) return badInput(variants.string() + ": cannot list: " + error.message());
    std::sort(files.begin(), files.end());
    if (files.empty()) return badInput(variants.string() + ": no material .json files");
    return files;
}

Result<std::vector<VariantFile>> loadVariantFolder(const std::filesystem::path& folder,
                                                   const MaterialFile& context) {
    auto files = variantFolderFiles(folder);
    if (!files) return files.error();
    std::vector<VariantFile> loaded;
    for (const auto& file : *files) {
        auto material = loadMaterial(file, context);
        if (!material) return material.error();
        loaded.push_back({file, std::move(material->file), std::move(material->warnings)});
    }
    return loaded;
}

}  // namespace matevo
