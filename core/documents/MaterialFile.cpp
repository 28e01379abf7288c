#include "documents/MaterialFile.h"

#include "documents/GenomeJson.h"
#include "documents/PresetFieldsJson.h"
#include "files/AtomicFile.h"
#include "files/InputFile.h"
#include "files/JsonReader.h"
#include "files/TextFile.h"
#include "genome/FamilyRules.h"

namespace matevo {

namespace {

namespace fs = std::filesystem;

fs::path resolvedTexture(const fs::path& folder, const std::string& name) {
    if (name.empty()) return {};
    return fs::absolute(folder / name).lexically_normal();
}

std::string writtenTexture(const fs::path& texture, const fs::path& folder) {
    if (folder.empty()) return texture.string();
    return texture.lexically_relative(fs::absolute(folder).lexically_normal()).string();
}

MaterialFile readMaterialFile(JsonReader& root, const fs::path& folder) {
    readFormatVersion(root, kMaterialFormatVersion);
    MaterialFile result;
    if (root.has("name")) result.name = root.string("name");
    result.material.family = readFamily(root, "family");
    result.material.baseKappa = readBaseKappa(root, result.material.family);
    result.material.genome = readFamilyGenome(root, "genome", result.material.family);
    const TextureNames textures = readTextures(root, result.material.family);
    result.roughnessTexture = resolvedTexture(folder, textures.roughness);
    result.baseColorTexture = resolvedTexture(folder, textures.baseColor);
    if (root.has("scene")) result.scene = readScene(root.object("scene"), false);
    if (result.scene.environment != "studio")
        result.scene.environment = resolvedTexture(folder, result.scene.environment).string();
    root.warnAboutUnknownFields();
    return result;
}

bool isMaterialFile(const nlohmann::json& json) {
    return json.is_object() && json.contains("format");
}

MaterialFile readAnyMaterial(const nlohmann::json& json, const fs::path& folder,
                             const MaterialFile& context, std::vector<std::string>& warnings,
                             bool& fromContext) {
    JsonReader root(json, "", warnings);
    if (isMaterialFile(json)) {
        if (root.string("format") != kMaterialFormat)
            root.fail("format", std::string("must be \"") + kMaterialFormat + "\"");
        return readMaterialFile(root, folder);
    }
    if (root.has("best_material")) {  // an evolve report: its best material
        const auto& best = json["best_material"];
        JsonReader reader = root.object("best_material");  // checks that it is an object
        if (!isMaterialFile(best)) reader.fail("format", "missing");
        if (reader.string("format") != kMaterialFormat)
            reader.fail("format", std::string("must be \"") + kMaterialFormat + "\"");
        return readMaterialFile(reader, folder);
    }
    if (root.has("target") && root.has("ga"))
        throw JsonFieldError("a preset, not a material (give it with --preset)");
    // A genome without its family: the context supplies the rest.
    fromContext = true;
    MaterialFile result = context;
    if (root.has("genome")) {  // a population entry; its scores are not part of the material
        result.material.genome = readFamilyGenome(root, "genome", context.material.family);
    } else {
        result.material.genome = readGenome(root);
        root.warnAboutUnknownFields();
        if (auto problem = validateGenome(result.material.genome, context.material.family))
            throw JsonFieldError(*problem + " (family " + describe(context.material.family) + ")");
    }
    return result;
}

}  // namespace

MaterialFile materialFromPreset(const Preset& preset, const fs::path& presetFile,
                                const Genome& genome, std::string name) {
    const fs::path folder = presetFile.parent_path();
    MaterialFile material{std::move(name), materialOf(genome, preset.family, preset.baseKappa),
                          resolvedTexture(folder, preset.roughnessTexture),
                          resolvedTexture(folder, preset.baseColorTexture), preset.scene};
    if (material.scene.environment != "studio")
        material.scene.environment = resolvedTexture(folder, material.scene.environment).string();
    return material;
}

nlohmann::ordered_json materialToJson(const MaterialFile& material, const fs::path& folder) {
    nlohmann::ordered_json json = {{"format", kMaterialFormat},
                                   {"format_version", kMaterialFormatVersion}};
    if (!material.name.empty()) json["name"] = material.name;
    json["family"] = familyToJson(material.material.family);
    if (material.material.family.base == Base::Conductor)
        json["base_kappa"] = material.material.baseKappa;
    json["genome"] = genomeToJson(material.material.genome);
    nlohmann::ordered_json textures = nlohmann::ordered_json::object();
    if (!material.roughnessTexture.empty())
        textures["roughness"] = writtenTexture(material.roughnessTexture, folder);
    if (!material.baseColorTexture.empty())
        textures["base_color"] = writtenTexture(material.baseColorTexture, folder);
    if (!textures.empty()) json["textures"] = std::move(textures);
    json["scene"] = sceneToJson(material.scene);
    if (material.scene.environment != "studio")
        json["scene"]["environment"] = writtenTexture(material.scene.environment, folder);
    return json;
}

Status saveMaterial(const MaterialFile& material, const fs::path& file) {
    const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
    return writeFileAtomically(file, materialToJson(material, folder).dump(2) + "\n");
}

Result<LoadedMaterial> parseMaterial(const std::string& jsonText, const std::string& sourceName,
                                     const fs::path& folder, const MaterialFile& context) {
    LoadedMaterial loaded;
    auto file = readJsonDocument<MaterialFile>(
        jsonText, sourceName, loaded.warnings, [&](const nlohmann::json& json) {
            return readAnyMaterial(json, folder, context, loaded.warnings, loaded.fromContext);
        });
    if (!file) return file.error();
    loaded.file = std::move(*file);
    return loaded;
}

Result<LoadedMaterial> loadMaterial(const fs::path& file, const MaterialFile& context) {
    auto text = readTextFile(file);
    if (!text) return text.error();
    const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
    auto loaded = parseMaterial(*text, file.string(), folder, context);
    if (!loaded) return loaded;
    for (const auto& [field, path] :
         {std::pair{"textures.roughness", loaded->file.roughnessTexture},
          std::pair{"textures.base_color", loaded->file.baseColorTexture}}) {
        // A path that cannot even be looked at (a symlink loop, a name too long) is the user's
        // mistake too, not an internal error.
        if (path.empty()) continue;
        if (auto readable = checkInputFile(path); !readable)
            return withContext(readable.error(), displayPath(file) + ": " + field);
    }
    return loaded;
}

}  // namespace matevo
