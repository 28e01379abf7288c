#include "PresetFiles.h"

#include <system_error>

namespace matevo::ui {
namespace {

namespace fs = std::filesystem;

fs::path resolved(const fs::path& path) {
    std::error_code error;
    fs::path absolute = fs::absolute(path, error);
    if (error) return path.lexically_normal();
    fs::path canonical = fs::weakly_canonical(absolute, error);
    return error ? absolute.lexically_normal() : canonical;
}

fs::path folderOf(const fs::path& file) {
    return resolved(file.has_parent_path() ? file.parent_path() : fs::path("."));
}

std::string rebased(const std::string& texture, const fs::path& fromFolder) {
    if (texture.empty() || fs::path(texture).is_absolute()) return texture;
    return (fromFolder / texture).lexically_normal().string();
}

}  // namespace

bool isInside(const fs::path& file, const fs::path& folder) {
    if (folder.empty()) return false;
    const fs::path inner = resolved(file);
    const fs::path outer = resolved(folder);
    auto innerPart = inner.begin();
    for (const fs::path& part : outer) {
        if (part.empty()) continue;  // a trailing separator
        if (innerPart == inner.end() || *innerPart != part) return false;
        ++innerPart;
    }
    return innerPart != inner.end();
}

fs::path suggestSavePath(const PresetFolders& folders, const fs::path& current,
                         const std::string& presetName) {
    if (!current.empty() && !isInside(current, folders.shipped)) return current;
    const fs::path name = current.empty() ? fs::path(presetName + ".json") : current.filename();
    return folders.user.empty() ? name : folders.user / name;
}

Preset rebaseTextures(Preset preset, const fs::path& from, const fs::path& to) {
    const fs::path fromFolder = folderOf(from);
    if (from.empty() || fromFolder == folderOf(to)) return preset;
    preset.roughnessTexture = rebased(preset.roughnessTexture, fromFolder);
    preset.baseColorTexture = rebased(preset.baseColorTexture, fromFolder);
    return preset;
}

Status createParentFolder(const fs::path& file) {
    if (!file.has_parent_path()) return Ok{};
    std::error_code error;
    fs::create_directories(file.parent_path(), error);
    if (error)
        return badInput("cannot create the folder " + file.parent_path().string() + " (" +
                        error.message() + ")");
    return Ok{};
}

}  // namespace matevo::ui
