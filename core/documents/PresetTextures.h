#pragma once
// The scene textures a preset or a material file names, loaded through scene/SceneTextures.h.
#include <filesystem>
#include <string>

#include "common/Result.h"
#include "documents/MaterialFile.h"
#include "documents/Preset.h"
#include "scene/SceneTextures.h"

namespace matevo {

// Loads the preset's textures, and its environment in the environment scene mode; their names
// are relative to the preset file's folder. Errors name the preset file, the field and the
// image file.
Result<SceneTextures> loadSceneTextures(const Preset& preset,
                                        const std::filesystem::path& presetFile);

// The files loadSceneTextures(preset, presetFile) reads: while they stay the same, so do the
// textures, and a renderer keeps its own (the editor's, while a target slider is dragged).
struct TextureSources {
    std::filesystem::path roughness;
    std::filesystem::path baseColor;
    std::string environment;  // empty outside the environment scene mode

    bool operator==(const TextureSources&) const = default;
};
TextureSources textureSourcesOf(const Preset& preset, const std::filesystem::path& presetFile);

// Loads a material file's textures (absolute paths); errors name `sourceName` and the field.
Result<SceneTextures> loadSceneTextures(const MaterialFile& material,
                                        const std::string& sourceName);

}  // namespace matevo
