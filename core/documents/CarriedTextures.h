#pragma once
// A set folder carries the files its materials read (roughness and base colour textures, an
// environment map), so that the folder can be moved, copied or mailed and still renders,
// exports and merges: each is copied to SET/textures/ROLE.EXT (roughness.png, base_color.png,
// environment.hdr; one file per role, since a set comes from one preset) and the material
// points there, which its file then writes as a path relative to itself (documents/MaterialFile.h).
#include <filesystem>

#include "common/Result.h"
#include "documents/MaterialFile.h"

namespace matevo {

// "textures": the folder inside a set that holds its carried files.
std::filesystem::path carriedTextureFolder(const std::filesystem::path& setFolder);

// `material` with its files copied into the set folder (atomically; a file already there with
// the same contents is left as it is) and its paths on the copies. Errors name the file.
Result<MaterialFile> carryTextures(const MaterialFile& material,
                                   const std::filesystem::path& setFolder);

}  // namespace matevo
