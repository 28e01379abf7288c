#pragma once
// Where the editor's presets come from and go. Shipped presets are read-only (one Enter must
// never overwrite them); "Save as" starts in the user's preset folder; saving creates missing
// folders and keeps texture references working from the new place.
#include <filesystem>
#include <string>

#include "common/Result.h"
#include "documents/Preset.h"

namespace matevo::ui {

struct PresetFolders {
    std::filesystem::path shipped;  // presets that come with matevo; empty: none
    std::filesystem::path user;     // where "Save as" starts; empty: the current directory
    std::filesystem::path exports;  // where "Export set…" starts; empty: the current directory
};

// `file` lies inside `folder` (after resolving `..` and symbolic links where they exist).
bool isInside(const std::filesystem::path& file, const std::filesystem::path& folder);

// The path "Save as" offers: the current file when it is the user's own, else the user's
// folder with the current file name (or the preset's name).
std::filesystem::path suggestSavePath(const PresetFolders& folders,
                                      const std::filesystem::path& current,
                                      const std::string& presetName);

// Texture paths in a preset are relative to its file's folder. Saved elsewhere, they are made
// absolute so the new file still finds them; unchanged when the folder stays the same.
Preset rebaseTextures(Preset preset, const std::filesystem::path& from,
                      const std::filesystem::path& to);

// Creates the folder `file` goes into; the error names the folder and the reason.
Status createParentFolder(const std::filesystem::path& file);

}  // namespace matevo::ui
