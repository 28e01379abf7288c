#pragma once
// The JSON fields that presets share with material files and GA checkpoints: the family, the
// conductor base's kappa, the textures, the scene and the GA settings. Readers throw
// JsonFieldError naming the field (JsonReader.h); writers keep the keys in the order a person
// reads them.
#include <array>
#include <string>

#include <nlohmann/json.hpp>

#include "evolve/GaSettings.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"
#include "scene/SceneSettings.h"

namespace matevo {

class JsonReader;

// Reads `key` of `parent` as a family and checks it (Table 2 textures only the rough layer).
MaterialFamily readFamily(JsonReader& parent, const std::string& key);
nlohmann::ordered_json familyToJson(const MaterialFamily& family);
// The genome under `key`, which must be a member of `family` (Table 2).
Genome readFamilyGenome(JsonReader& parent, const std::string& key, const MaterialFamily& family);

// "base_kappa" of `parent`: required and positive for a conductor base; a dielectric has none
// (absent or zeros).
std::array<double, 3> readBaseKappa(JsonReader& parent, const MaterialFamily& family);

// "textures" of `parent` (optional): file names as written. A family with a textured layer
// needs a roughness texture.
struct TextureNames {
    std::string roughness;
    std::string baseColor;
};
TextureNames readTextures(JsonReader& parent, const MaterialFamily& family);

SceneSettings readScene(JsonReader reader);
nlohmann::ordered_json sceneToJson(const SceneSettings& scene);

GaSettings readGaSettings(JsonReader reader);
nlohmann::ordered_json gaSettingsToJson(const GaSettings& ga);

}  // namespace matevo
