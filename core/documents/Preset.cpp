#include "documents/Preset.h"

#include <nlohmann/json.hpp>

#include <system_error>

#include "documents/GenomeJson.h"
#include "documents/PresetFieldsJson.h"
#include "files/AtomicFile.h"
#include "files/InputFile.h"
#include "files/JsonReader.h"
#include "files/TextFile.h"
#include "genome/FamilyRules.h"

namespace matevo {

namespace {

KeptMaterial readKept(JsonReader& reader) {
    KeptMaterial kept;
    kept.name = reader.string("name");
    kept.family = readFamily(reader, "family");
    kept.genome = readFamilyGenome(reader, "genome", kept.family);
    reader.warnAboutUnknownFields();
    return kept;
}

SavedVariantSet readVariantSet(JsonReader& reader) {
    SavedVariantSet set;
    set.family = readFamily(reader, "family");
    set.target = readFamilyGenome(reader, "target", set.family);
    set.baseKappa = readBaseKappa(reader, set.family);
    for (JsonReader entry : reader.objects("variants")) {
        Genome genome = readFamilyGenome(entry, "genome", set.family);
        if (entry.has("kappa")) {
            const auto kappa = entry.numbers<3>("kappa", 0.0, 100.0);
            for (std::size_t c = 0; c < 3; ++c) genome[kKappaR + c] = kappa[c];
        }
        entry.warnAboutUnknownFields();
        set.variants.push_back(genome);
    }
    reader.warnAboutUnknownFields();
    return set;
}

Preset readPreset(JsonReader& root) {
    const int version =
        root.has("format_version") ? readFormatVersion(root, kPresetFormatVersion) : 1;
    Preset preset;
    preset.name = root.string("name");
    if (root.has("description")) preset.description = root.string("description");
    preset.family = readFamily(root, "family");
    // The target must be a member of its own family, or the GA could never approach it.
    preset.target = readFamilyGenome(root, "target", preset.family);
    preset.baseKappa = readBaseKappa(root, preset.family);
    auto textures = readTextures(root, preset.family);
    preset.roughnessTexture = std::move(textures.roughness);
    preset.baseColorTexture = std::move(textures.baseColor);
    preset.ga = readGaSettings(root.object("ga"));
    if (root.has("fitness")) {
        const std::string fitness = root.string("fitness");
        if (fitness != "genotype" && fitness != "image")
            root.fail("fitness", "unknown value '" + fitness + "' (expected genotype or image)");
        preset.imageFitness = fitness == "image";
    }
    if (root.has("scene")) preset.scene = readScene(root.object("scene"), version == 1);
    if (root.has("kept"))
        for (JsonReader entry : root.objects("kept")) preset.kept.push_back(readKept(entry));
    if (root.has("variant_set")) {
        JsonReader set = root.object("variant_set");
        preset.variantSet = readVariantSet(set);
    }
    root.warnAboutUnknownFields();
    return preset;
}

// The target's refractive indices and roughnesses are always written: a genome without them
// is no material.
nlohmann::ordered_json minimalGenomeJson(const Genome& genome) {
    return changedFields(genomeToJson(genome), genomeToJson(Genome{}),
                         {"eta1", "eta2", "alpha1", "alpha2"});
}

nlohmann::ordered_json minimalFamilyJson(const MaterialFamily& family) {
    return changedFields(familyToJson(family), familyToJson(MaterialFamily{}),
                         {"coat", "base", "medium"});
}

}  // namespace

Result<LoadedPreset> parsePreset(const std::string& jsonText, const std::string& sourceName) {
    std::vector<std::string> warnings;
    auto preset =
        readJsonDocument<Preset>(jsonText, sourceName, warnings, [&](const nlohmann::json& json) {
            JsonReader root(json, "", warnings);
            return readPreset(root);
        });
    if (!preset) return preset.error();
    return LoadedPreset{std::move(*preset), std::move(warnings)};
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
            return badInput(file.string() + ": " + field + ": no such file '" +
                            displayPath(file.parent_path() / name) + "'");
    }
    return loaded;
}

std::string serializePreset(const Preset& preset) {
    const Preset defaults;
    nlohmann::ordered_json json = {{"format_version", kPresetFormatVersion}, {"name", preset.name}};
    if (!preset.description.empty()) json["description"] = preset.description;
    json["family"] = minimalFamilyJson(preset.family);
    json["target"] = minimalGenomeJson(preset.target);
    if (preset.family.base == Base::Conductor) json["base_kappa"] = preset.baseKappa;
    nlohmann::ordered_json textures = nlohmann::ordered_json::object();
    if (!preset.roughnessTexture.empty()) textures["roughness"] = preset.roughnessTexture;
    if (!preset.baseColorTexture.empty()) textures["base_color"] = preset.baseColorTexture;
    if (!textures.empty()) json["textures"] = std::move(textures);
    json["ga"] = changedFields(gaSettingsToJson(preset.ga), gaSettingsToJson(defaults.ga),
                               {"population", "generations"});
    if (preset.imageFitness) json["fitness"] = "image";
    if (auto scene = changedFields(sceneToJson(preset.scene), sceneToJson(defaults.scene));
        !scene.empty())
        json["scene"] = std::move(scene);
    if (!preset.kept.empty()) {
        nlohmann::ordered_json kept = nlohmann::ordered_json::array();
        for (const KeptMaterial& material : preset.kept)
            kept.push_back({{"name", material.name},
                            {"family", minimalFamilyJson(material.family)},
                            {"genome", minimalGenomeJson(material.genome)}});
        json["kept"] = std::move(kept);
    }
    if (const auto& set = preset.variantSet) {
        nlohmann::ordered_json saved = {{"family", minimalFamilyJson(set->family)},
                                        {"target", minimalGenomeJson(set->target)}};
        if (set->family.base == Base::Conductor) saved["base_kappa"] = set->baseKappa;
        nlohmann::ordered_json variants = nlohmann::ordered_json::array();
        for (const Genome& genome : set->variants) {
            nlohmann::ordered_json variant = {{"genome", minimalGenomeJson(genome)}};
            if (genome.carriesKappa()) variant["kappa"] = genome.kappa();
            variants.push_back(std::move(variant));
        }
        saved["variants"] = std::move(variants);
        json["variant_set"] = std::move(saved);
    }
    return json.dump(2) + "\n";
}

std::vector<Genome> keptGenomesOfFamily(const Preset& preset) {
    std::vector<Genome> genomes;
    for (const KeptMaterial& kept : preset.kept)
        if (kept.family == preset.family) genomes.push_back(kept.genome);
    return genomes;
}

bool variantSetMadeForAnotherTarget(const Preset& preset) {
    const auto& set = preset.variantSet;
    return set && (set->family != preset.family || set->target != preset.target ||
                   (preset.family.base == Base::Conductor && set->baseKappa != preset.baseKappa));
}

Status savePreset(const Preset& preset, const std::filesystem::path& file) {
    // A save killed earlier (kill -9, power loss) may have left its temporary file here.
    removeStaleTemporaryFilesBeside(file);
    return writeFileAtomically(file, serializePreset(preset));
}

}  // namespace matevo
