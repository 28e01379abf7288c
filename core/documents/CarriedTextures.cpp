#include "documents/CarriedTextures.h"

#include "files/AtomicFile.h"
#include "files/InputFile.h"

namespace matevo {

namespace {

namespace fs = std::filesystem;

// Copies `file` to FOLDER/ROLE.EXT unless it is that file already; returns the copy's path.
Result<fs::path> carry(const fs::path& file, const std::string& role, const fs::path& folder) {
    const fs::path copy =
        fs::absolute(folder / (role + file.extension().string())).lexically_normal();
    std::error_code error;
    if (fs::equivalent(file, copy, error)) return copy;
    auto bytes = readInputFile(file, kMaxImageFileBytes);
    if (!bytes) return bytes.error();
    if (fs::is_regular_file(copy, error)) {
        auto present = readInputFile(copy, kMaxImageFileBytes);
        if (present && *present == *bytes) return copy;
    }
    fs::create_directories(folder, error);
    if (error)
        return badInput("cannot create folder '" + folder.string() + "' (" + error.message() + ")");
    if (auto written = writeFileAtomically(copy, *bytes); !written) return written.error();
    return copy;
}

}  // namespace

fs::path carriedTextureFolder(const fs::path& setFolder) { return setFolder / "textures"; }

Result<MaterialFile> carryTextures(const MaterialFile& material, const fs::path& setFolder) {
    MaterialFile carried = material;
    const fs::path folder = carriedTextureFolder(setFolder);
    for (auto [path, role] : {std::pair{&carried.roughnessTexture, "roughness"},
                              std::pair{&carried.baseColorTexture, "base_color"}}) {
        if (path->empty()) continue;
        auto copy = carry(*path, role, folder);
        if (!copy) return copy.error();
        *path = *copy;
    }
    if (carried.scene.environment != "studio") {
        auto copy = carry(carried.scene.environment, "environment", folder);
        if (!copy) return copy.error();
        carried.scene.environment = copy->string();
    }
    return carried;
}

}  // namespace matevo
