#include "io/Preset.h"

#include <nlohmann/json.hpp>

#include "genome/FamilyRules.h"
#include "io/AtomicFile.h"
#include "io/GenomeJson.h"
#include "io/JsonReader.h"
#include "io/MaterialFieldsJson.h"
#include "io/TextFile.h"

namespace matevo {

namespace {

GaSettings readGaSettings(JsonReader reader) {
    GaSettings ga;
    ga.population = int(reader.integer("population", 2, kMaxPopulation));
    ga.generations = int(reader.integer("generations", 0, kMaxGenerations));
    if (reader.has("metric"))
        ga.metric =
            reader.enumeration("metric", parseDistanceMetric, "chebyshev, euclidean or manhattan");
    if (reader.has("weights")) ga.weights = reader.numbers<kChromosomeCount>("weights", 0.0, 1e6);
    if (reader.has("normalize_by_range"))
        ga.normalizeByRange = reader.boolean("normalize_by_range");
    if (reader.has("elitism")) ga.elitism = int(reader.integer("elitism", 0, ga.population - 1));
    if (reader.has("seed")) ga.seed = reader.unsignedInteger("seed");
    reader.warnAboutUnknownFields();
    return ga;
}

Preset readPreset(JsonReader& root) {
    Preset preset;
    preset.name = root.string("name");
    if (root.has("description")) preset.description = root.string("description");
    preset.family = readFamily(root, "family");
    {
        JsonReader target = root.object("target");
        preset.target = readGenome(target);
        target.warnAboutUnknownFields();
    }
    // The target must be a member of its own family, or the GA could never approach it.
    if (auto problem = validateGenome(preset.target, preset.family)) root.fail("target", *problem);
    preset.baseKappa = readBaseKappa(root, preset.family);
    auto textures = readTextures(root, preset.family);
    preset.roughnessTexture = std::move(textures.roughness);
    preset.baseColorTexture = std::move(textures.baseColor);
    preset.ga = readGaSettings(root.object("ga"));
    if (root.has("scene")) preset.scene = readScene(root.object("scene"));
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
        if (!name.empty() && !std::filesystem::is_regular_file(file.parent_path() / name))
            return Error{file.string() + ": " + field + ": no such file '" +
                         (file.parent_path() / name).string() + "'"};
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
        {"scene", sceneToJson(preset.scene)},
    };
    if (preset.family.base == Base::Conductor) json["base_kappa"] = preset.baseKappa;
    return json.dump(2) + "\n";
}

Status savePreset(const Preset& preset, const std::filesystem::path& file) {
    return writeFileAtomically(file, serializePreset(preset));
}

}  // namespace matevo
