#pragma once
// The JSON fields that presets share with material files and GA checkpoints: the family, the
// conductor base's kappa, the textures, the scene and the GA settings. Readers throw
// JsonFieldError naming the field (JsonReader.h); writers keep the keys in the order a person
// reads them.
#include <array>
#include <initializer_list>
#include <string>

#include <nlohmann/json.hpp>

#include "evolve/GaSettings.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"
#include "scene/SceneSettings.h"

namespace matevo {

class JsonReader;

// "format_version" of `root`: an integer from 1 up to `newest`, the newest this matevo reads
// (a newer file is refused rather than misread).
int readFormatVersion(JsonReader& root, int newest);

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

// `writtenBeforeModes`: the document comes from before scene modes existed (a preset of format
// 1), where an environment radiance without a mode meant the ambient look: it is then ignored
// with a warning rather than switched silently.
SceneSettings readScene(JsonReader reader, bool writtenBeforeModes);
nlohmann::ordered_json sceneToJson(const SceneSettings& scene);

GaSettings readGaSettings(JsonReader reader);
nlohmann::ordered_json gaSettingsToJson(const GaSettings& ga);

// The fields of the object `json` whose values differ from those of `defaults` (a writer's
// output for a default-constructed value), plus the fields named in `required`, in `json`'s
// order: what a minimal file writes, so that it shows what was chosen and diffs well.
nlohmann::ordered_json changedFields(const nlohmann::ordered_json& json,
                                     const nlohmann::ordered_json& defaults,
                                     std::initializer_list<const char*> required = {});

}  // namespace matevo
