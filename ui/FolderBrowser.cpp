#include "FolderBrowser.h"

#include <algorithm>
#include <system_error>

#include <imgui.h>

namespace matevo::ui {

namespace fs = std::filesystem;

fs::path browsedFolder(const std::string& path) {
    std::error_code error;
    if (path.empty()) return ".";
    if (fs::is_directory(path, error)) return path;
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

std::vector<FolderEntry> listFolder(const fs::path& folder) {
    std::vector<FolderEntry> folders, files;
    std::error_code error;
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name.front() == '.') continue;
        std::error_code kind;
        (it->is_directory(kind) ? folders : files).push_back({name, it->is_directory(kind)});
    }
    if (error) return {};
    const auto byName = [](const FolderEntry& a, const FolderEntry& b) { return a.name < b.name; };
    std::sort(folders.begin(), folders.end(), byName);
    std::sort(files.begin(), files.end(), byName);
    std::vector<FolderEntry> entries;
    const fs::path absolute = fs::absolute(folder, error);
    if (!error && absolute.has_relative_path()) entries.push_back({"..", true});
    entries.insert(entries.end(), folders.begin(), folders.end());
    entries.insert(entries.end(), files.begin(), files.end());
    return entries;
}

std::string pathAfterChoosing(const std::string& path, const FolderEntry& entry) {
    const fs::path folder = browsedFolder(path);
    if (!entry.folder) return (folder / entry.name).string();
    std::error_code error;
    fs::path absolute = fs::absolute(folder, error).lexically_normal();
    if (!absolute.has_filename()) absolute = absolute.parent_path();  // "a/b/" is "a/b"
    const fs::path into = entry.name == ".." ? absolute.parent_path() : folder / entry.name;
    // A typed file name (Save as) stays; a folder path ends in a separator.
    const bool typedFile = !path.empty() && !fs::is_directory(path, error);
    return typedFile ? (into / fs::path(path).filename()).string() : (into / "").string();
}

bool drawFolderBrowser(std::string& path, float height) {
    bool chosen = false;
    if (!ImGui::BeginChild("##folder", ImVec2(0.0f, height), true)) {
        ImGui::EndChild();
        return false;
    }
    const std::string shown = path;  // the listing of this frame, even if a click changes path
    for (const FolderEntry& entry : listFolder(browsedFolder(shown))) {
        const std::string label = entry.folder ? entry.name + "/" : entry.name;
        const bool current = !entry.folder && fs::path(shown).filename().string() == entry.name;
        if (ImGui::Selectable(label.c_str(), current, ImGuiSelectableFlags_AllowDoubleClick)) {
            path = pathAfterChoosing(shown, entry);
            chosen = !entry.folder && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
        }
    }
    ImGui::EndChild();
    return chosen;
}

}  // namespace matevo::ui
