#include "io/Preset.h"

#include <nlohmann/json.hpp>

#include <system_error>

#include "genome/FamilyRules.h"
#include "io/AtomicFile.h"
#include "io/GenomeJson.h"
#include "io/InputFile.h"
#include "io/JsonReader.h"
#include "io/TextFile.h"

namespace matevo {

namespace {

template <typename Enum>
Enum readEnum(JsonReader& reader, const std::string& key,
              std::optional<Enum> (*parse)(std::string_view), const char* expected) {
    auto text = reader.string(key);
    auto value = parse(text);
    if (!value) reader.fail(key, "unknown value '" + text + "' (expected " + expected + ")");
    return *value;
}

MaterialFamily readFamily(JsonReader reader) {
    MaterialFamily family;
    family.coat = readEnum(reader, "coat", parseCoat, "roughcoat or clearcoat");
    family.base = readEnum(reader, "base", parseBase, "conductor or dielectric");
    family.hasMedium = reader.boolean("medium");
    if (reader.has("textured_layer"))
        family.texturedLayer =
            readEnum(reader, "textured_layer", parseTexturedLayer, "none, top or bottom");
    reader.warnAboutUnknownFields();
    return family;
}

GaSettings readGaSettings(JsonReader reader) {
    GaSettings ga;
    ga.population = int(reader.integer("population", 2, kMaxPopulation));
    ga.generations = int(reader.integer("generations", 0, kMaxGenerations));
    if (reader.has("metric"))
        ga.metric =
            readEnum(reader, "metric", parseDistanceMetric, "chebyshev, euclidean or manhattan");
    if (reader.has("weights")) ga.weights = reader.numbers<kPaperChromosomeCount>("weights", 0.0, 1e6);
    if (reader.has("normalize_by_range"))
        ga.normalizeByRange = reader.boolean("normalize_by_range");
    if (reader.has("elitism")) ga.elitism = int(reader.integer("elitism", 0, ga.population - 1));
    if (reader.has("seed")) ga.seed = reader.unsignedInteger("seed");
    reader.warnAboutUnknownFields();
    return ga;
}

SceneSettings readScene(JsonReader reader) {
    SceneSettings scene;
    if (reader.has("mode"))
        scene.mode = readEnum(reader, "mode", parseSceneMode, "paper, ambient or environment");
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
        if (!reader.has("mode"))
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

void readTextures(JsonReader reader, Preset& preset) {
    if (reader.has("roughness")) preset.roughnessTexture = reader.string("roughness");
    if (reader.has("base_color")) preset.baseColorTexture = reader.string("base_color");
    reader.warnAboutUnknownFields();
}

MaterialFamily readValidFamily(JsonReader& parent, const std::string& key) {
    MaterialFamily family = readFamily(parent.object(key));
    if (auto problem = validateFamily(family)) parent.fail(key, *problem);
    return family;
}

// The genome under `key`, which must be a member of `family` (Table 2).
Genome readFamilyGenome(JsonReader& parent, const std::string& key, const MaterialFamily& family) {
    JsonReader reader = parent.object(key);
    Genome genome = readGenome(reader);
    reader.warnAboutUnknownFields();
    if (auto problem = validateGenome(genome, family)) parent.fail(key, *problem);
    return genome;
}

KeptMaterial readKept(JsonReader& reader) {
    KeptMaterial kept;
    kept.name = reader.string("name");
    kept.family = readValidFamily(reader, "family");
    kept.genome = readFamilyGenome(reader, "genome", kept.family);
    reader.warnAboutUnknownFields();
    return kept;
}

Preset readPreset(JsonReader& root) {
    Preset preset;
    preset.name = root.string("name");
    if (root.has("description")) preset.description = root.string("description");
    preset.family = readValidFamily(root, "family");
    // The target must be a member of its own family, or the GA could never approach it.
    preset.target = readFamilyGenome(root, "target", preset.family);
    if (preset.family.base == Base::Conductor) {
        preset.baseKappa = root.numbers<3>("base_kappa", 0.0, 100.0);
        const auto& k = preset.baseKappa;
        if (k[0] <= 0.0 && k[1] <= 0.0 && k[2] <= 0.0)
            root.fail("base_kappa", "a conductor base needs a positive extinction coefficient");
    } else if (root.has("base_kappa")) {
        root.numbers<3>("base_kappa", 0.0, 0.0);  // a dielectric has none: only zeros are valid
    }
    if (root.has("textures")) readTextures(root.object("textures"), preset);
    if (preset.family.texturedLayer != TexturedLayer::None && preset.roughnessTexture.empty())
        root.fail("textures.roughness", "a family with a textured layer needs a roughness texture");
    preset.ga = readGaSettings(root.object("ga"));
    if (root.has("scene")) preset.scene = readScene(root.object("scene"));
    if (root.has("kept"))
        for (JsonReader entry : root.objects("kept")) preset.kept.push_back(readKept(entry));
    root.warnAboutUnknownFields();
    return preset;
}

}  // namespace

Result<LoadedPreset> parsePreset(const std::string& jsonText, const std::string& sourceName) {
    LoadedPreset loaded;
    try {
        auto json = nlohmann::json::parse(jsonText);
        JsonReader root(json, "", loaded.warnings);
        loaded.preset = readPreset(root);
    } catch (const nlohmann::json::exception& error) {
        return Error{sourceName + ": not valid JSON (" + error.what() + ")"};
    } catch (const JsonFieldError& error) {
        return Error{sourceName + ": " + error.what()};
    }
    for (auto& warning : loaded.warnings) warning = sourceName + ": " + warning;
    return loaded;
}

Result<LoadedPreset> loadPreset(const std::filesystem::path& file) {
    auto text = readTextFile(file);
    if (!text) return text.error();
    auto loaded = parsePreset(*text, file.string());
    if (!loaded) return loaded;
    // Texture names are relative to the preset's folder: they must exist there.
    for (const auto& [field, name] :
         {std::pair{"textures.roughness", loaded->preset.roughnessTexture},
          std::pair{"textures.base_color", loaded->preset.baseColorTexture}}) {
        // The error_code overload: a symlink loop or an over-long name is an answer, not a throw.
        std::error_code error;
        if (!name.empty() && !std::filesystem::is_regular_file(file.parent_path() / name, error))
            return Error{file.string() + ": " + field + ": no such file '" +
                         displayPath(file.parent_path() / name) + "'"};
    }
    return loaded;
}

std::string serializePreset(const Preset& preset) {
    nlohmann::json json = {
        {"name", preset.name},
        {"description", preset.description},
        {"family", familyToJson(preset.family)},
        {"target", genomeToJson(preset.target)},
        {"textures",
         {{"roughness", preset.roughnessTexture}, {"base_color", preset.baseColorTexture}}},
        {"ga",
         {{"population", preset.ga.population},
          {"generations", preset.ga.generations},
          {"metric", toString(preset.ga.metric)},
          {"weights", preset.ga.weights},
          {"normalize_by_range", preset.ga.normalizeByRange},
          {"elitism", preset.ga.elitism},
          {"seed", preset.ga.seed}}},
        {"scene",
         {{"mode", toString(preset.scene.mode)},
          {"image_size", preset.scene.imageSize},
          {"camera_position", preset.scene.cameraPosition},
          {"field_of_view_degrees", preset.scene.fieldOfViewDegrees},
          {"light_direction", preset.scene.lightDirection},
          {"light_radiance", preset.scene.lightRadiance},
          {"environment_radiance", preset.scene.environmentRadiance},
          {"environment", preset.scene.environment}}},
    };
    if (preset.family.base == Base::Conductor) json["base_kappa"] = preset.baseKappa;
    if (!preset.kept.empty()) {
        nlohmann::json kept = nlohmann::json::array();
        for (const KeptMaterial& material : preset.kept)
            kept.push_back({{"name", material.name},
                            {"family", familyToJson(material.family)},
                            {"genome", genomeToJson(material.genome)}});
        json["kept"] = kept;
    }
    return json.dump(2) + "\n";
}

std::vector<Genome> keptGenomesOfFamily(const Preset& preset) {
    std::vector<Genome> genomes;
    for (const KeptMaterial& kept : preset.kept)
        if (kept.family == preset.family) genomes.push_back(kept.genome);
    return genomes;
}

Status savePreset(const Preset& preset, const std::filesystem::path& file) {
    // A save killed earlier (kill -9, power loss) may have left its temporary file here.
    removeStaleTemporaryFiles(file.has_parent_path() ? file.parent_path() : ".");
    return writeFileAtomically(file, serializePreset(preset));
}

}  // namespace matevo
