#include "documents/PresetTextures.h"

namespace matevo {

namespace {

std::filesystem::path besidePreset(const std::filesystem::path& presetFile,
                                   const std::string& name) {
    return name.empty() ? std::filesystem::path() : presetFile.parent_path() / name;
}

}  // namespace

Result<SceneTextures> loadSceneTextures(const Preset& preset,
                                        const std::filesystem::path& presetFile) {
    return loadSceneTextures(besidePreset(presetFile, preset.roughnessTexture),
                             besidePreset(presetFile, preset.baseColorTexture), preset.scene,
                             presetFile.parent_path(), presetFile.string());
}

TextureSources textureSourcesOf(const Preset& preset, const std::filesystem::path& presetFile) {
    return {besidePreset(presetFile, preset.roughnessTexture),
            besidePreset(presetFile, preset.baseColorTexture),
            preset.scene.mode == SceneMode::Environment
                ? environmentFile(preset.scene, presetFile.parent_path())
                : std::string()};
}

Result<SceneTextures> loadSceneTextures(const MaterialFile& material,
                                        const std::string& sourceName) {
    return loadSceneTextures(material.roughnessTexture, material.baseColorTexture, material.scene,
                             {}, sourceName);
}

}  // namespace matevo
