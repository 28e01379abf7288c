#include "documents/PresetFieldsJson.h"

#include <algorithm>

#include "documents/GenomeJson.h"
#include "files/JsonReader.h"
#include "genome/FamilyRules.h"

namespace matevo {

int readFormatVersion(JsonReader& root, int newest) {
    const auto version = int(root.integer("format_version", 1, 1000000));
    if (version > newest)
        root.fail("format_version", "version " + std::to_string(version) +
                                        " is newer than this matevo reads (" +
                                        std::to_string(newest) + ")");
    return version;
}

MaterialFamily readFamily(JsonReader& parent, const std::string& key) {
    JsonReader reader = parent.object(key);
    MaterialFamily family;
    family.coat = reader.enumeration("coat", parseCoat, "roughcoat or clearcoat");
    family.base = reader.enumeration("base", parseBase, "conductor or dielectric");
    family.hasMedium = reader.boolean("medium");
    if (reader.has("textured_layer"))
        family.texturedLayer =
            reader.enumeration("textured_layer", parseTexturedLayer, "none, top or bottom");
    reader.warnAboutUnknownFields();
    if (auto problem = validateFamily(family)) parent.fail(key, *problem);
    return family;
}

Genome readFamilyGenome(JsonReader& parent, const std::string& key, const MaterialFamily& family) {
    JsonReader reader = parent.object(key);
    Genome genome = readGenome(reader);
    reader.warnAboutUnknownFields();
    if (auto problem = validateGenome(genome, family)) parent.fail(key, *problem);
    return genome;
}

nlohmann::ordered_json familyToJson(const MaterialFamily& family) {
    return {{"coat", toString(family.coat)},
            {"base", toString(family.base)},
            {"medium", family.hasMedium},
            {"textured_layer", toString(family.texturedLayer)}};
}

std::array<double, 3> readBaseKappa(JsonReader& parent, const MaterialFamily& family) {
    if (family.base == Base::Conductor) {
        auto kappa = parent.numbers<3>("base_kappa", 0.0, 100.0);
        if (kappa[0] <= 0.0 && kappa[1] <= 0.0 && kappa[2] <= 0.0)
            parent.fail("base_kappa", "a conductor base needs a positive extinction coefficient");
        return kappa;
    }
    if (parent.has("base_kappa"))
        parent.numbers<3>("base_kappa", 0.0, 0.0);  // a dielectric has none: only zeros are valid
    return {0.0, 0.0, 0.0};
}

TextureNames readTextures(JsonReader& parent, const MaterialFamily& family) {
    TextureNames names;
    if (parent.has("textures")) {
        JsonReader reader = parent.object("textures");
        if (reader.has("roughness")) names.roughness = reader.string("roughness");
        if (reader.has("base_color")) names.baseColor = reader.string("base_color");
        reader.warnAboutUnknownFields();
    }
    if (family.texturedLayer != TexturedLayer::None && names.roughness.empty())
        parent.fail("textures.roughness",
                    "a family with a textured layer needs a roughness texture");
    return names;
}

SceneSettings readScene(JsonReader reader, bool writtenBeforeModes) {
    SceneSettings scene;
    if (reader.has("mode"))
        scene.mode = reader.enumeration("mode", parseSceneMode, choiceNamesInWords(kSceneModes));
    if (reader.has("environment")) scene.environment = reader.string("environment");
    if (reader.has("image_size")) scene.imageSize = int(reader.integer("image_size", 8, 4096));
    if (reader.has("camera_position"))
        scene.cameraPosition = reader.numbers<3>("camera_position", -100.0, 100.0);
    if (reader.has("field_of_view_degrees"))
        scene.fieldOfViewDegrees = reader.number("field_of_view_degrees", 1.0, 170.0);
    if (reader.has("light_direction")) {
        scene.lightDirection = reader.numbers<3>("light_direction", -1e3, 1e3);
        const auto& d = scene.lightDirection;
        if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < 1e-12)
            reader.fail("light_direction", "must not be the zero vector");
    }
    if (reader.has("light_radiance"))
        scene.lightRadiance = reader.numbers<3>("light_radiance", 0.0, 1e4);
    if (reader.has("environment_radiance")) {
        scene.environmentRadiance = reader.numbers<3>("environment_radiance", 0.0, 1e4);
        // Presets from before the modes had no mode and meant the ambient look: say that it
        // changed rather than switch silently.
        if (writtenBeforeModes && !reader.has("mode"))
            reader.warn("environment_radiance",
                        "ignored: with no scene.mode the scene is the paper's (one light, no "
                        "ambient); set scene.mode to \"ambient\" to use it");
    }
    // The camera must sit outside the unit sphere it looks at.
    const auto& c = scene.cameraPosition;
    if (c[0] * c[0] + c[1] * c[1] + c[2] * c[2] <= 1.0 + 1e-6)
        reader.fail("camera_position", "must lie outside the unit sphere");
    reader.warnAboutUnknownFields();
    return scene;
}

nlohmann::ordered_json sceneToJson(const SceneSettings& scene) {
    return {{"mode", toString(scene.mode)},
            {"image_size", scene.imageSize},
            {"camera_position", scene.cameraPosition},
            {"field_of_view_degrees", scene.fieldOfViewDegrees},
            {"light_direction", scene.lightDirection},
            {"light_radiance", scene.lightRadiance},
            {"environment_radiance", scene.environmentRadiance},
            {"environment", scene.environment}};
}

GaSettings readGaSettings(JsonReader reader) {
    GaSettings ga;
    ga.population = int(reader.integer("population", 2, kMaxPopulation));
    ga.generations = int(reader.integer("generations", 0, kMaxGenerations));
    if (reader.has("metric"))
        ga.metric =
            reader.enumeration("metric", parseDistanceMetric, choiceNamesInWords(kDistanceMetrics));
    if (reader.has("weights"))
        ga.weights = reader.numbers<kPaperChromosomeCount>("weights", 0.0, kMaxChromosomeWeight);
    if (reader.has("normalize_by_range"))
        ga.normalizeByRange = reader.boolean("normalize_by_range");
    if (reader.has("elitism")) ga.elitism = int(reader.integer("elitism", 0, ga.population - 1));
    if (reader.has("seed")) ga.seed = reader.unsignedInteger("seed");
    reader.warnAboutUnknownFields();
    return ga;
}

nlohmann::ordered_json gaSettingsToJson(const GaSettings& ga) {
    return {{"population", ga.population},
            {"generations", ga.generations},
            {"metric", toString(ga.metric)},
            {"weights", ga.weights},
            {"normalize_by_range", ga.normalizeByRange},
            {"elitism", ga.elitism},
            {"seed", ga.seed}};
}

nlohmann::ordered_json changedFields(const nlohmann::ordered_json& json,
                                     const nlohmann::ordered_json& defaults,
                                     std::initializer_list<const char*> required) {
    nlohmann::ordered_json changed = nlohmann::ordered_json::object();
    for (const auto& field : json.items()) {
        const std::string& key = field.key();
        const bool isRequired = std::any_of(required.begin(), required.end(),
                                            [&](const char* name) { return key == name; });
        if (isRequired || !defaults.contains(key) || defaults.at(key) != field.value())
            changed[key] = field.value();
    }
    return changed;
}

}  // namespace matevo
