#pragma once
// A folder listing inside the Open and Save as dialogs (Debian's imgui 1.86 has no file
// browser): the folder the typed path points into, ".." and its sub-folders first, then its
// files. A click on a folder goes into it (keeping a typed file name), a click on a file takes
// its path, a double click on a file chooses it.
#include <filesystem>
#include <string>
#include <vector>

namespace matevo::ui {

struct FolderEntry {
    std::string name;
    bool folder = false;

    bool operator==(const FolderEntry&) const = default;
};

// The folder `path` lies in: `path` itself when it is a folder, else its parent ("." when it
// has none).
std::filesystem::path browsedFolder(const std::string& path);
// Its entries: ".." (unless at the root), the folders, then the files, each by name; hidden
// ones (a leading '.') left out. Empty when the folder cannot be read.
std::vector<FolderEntry> listFolder(const std::filesystem::path& folder);
// The path after clicking `entry` of the folder `path` lies in.
std::string pathAfterChoosing(const std::string& path, const FolderEntry& entry);

// Draws the listing, `height` pixels tall, editing `path`; true when a file was double-clicked.
bool drawFolderBrowser(std::string& path, float height);

}  // namespace matevo::ui
