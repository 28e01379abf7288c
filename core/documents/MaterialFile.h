#pragma once
// The one JSON form of a single material that matevo writes (evolve's best, variant files, the
// editor's "copy genome") and reads (render --genome, export): everything needed to render it on
// its own — family, the conductor base's kappa, the genome, the textures and the scene.
//   {"format": "matevo-material", "format_version": 1, "name": …, "family": {…},
//    "base_kappa": [r,g,b], "genome": {…}, "textures": {"roughness": …, "base_color": …},
//    "scene": {…}}
// Reading refuses anything outside Table 2 with the field named (the genome is never repaired:
// a silently changed material is worse than a clear refusal) and warns about unknown fields.
// Texture paths are written relative to the file's folder when the writer knows it, absolute
// otherwise (printed to stdout); relative ones are read relative to the file's folder.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/Result.h"
#include "documents/Preset.h"
#include "material/MaterialInstance.h"
#include "scene/SceneSettings.h"

namespace matevo {

inline constexpr const char* kMaterialFormat = "matevo-material";
inline constexpr int kMaterialFormatVersion = 1;

struct MaterialFile {
    std::string name;  // optional label, e.g. "validation_metal variant 3"
    MaterialInstance material;
    std::filesystem::path roughnessTexture;  // absolute; empty when unused
    std::filesystem::path baseColorTexture;  // absolute; empty when unused
    SceneSettings scene;

    bool operator==(const MaterialFile&) const = default;
};

// `genome` in the preset's context (with hue variety's kappa genes, its own kappa: materialOf);
// texture paths become absolute.
MaterialFile materialFromPreset(const Preset& preset, const std::filesystem::path& presetFile,
                                const Genome& genome, std::string name = {});

// `folder`: where the JSON will live (textures relative to it); empty for absolute paths.
nlohmann::ordered_json materialToJson(const MaterialFile& material,
                                      const std::filesystem::path& folder = {});
// Atomic (files/AtomicFile.h); textures relative to the file's folder.
Status saveMaterial(const MaterialFile& material, const std::filesystem::path& file);

struct LoadedMaterial {
    MaterialFile file;
    bool fromContext = false;  // a bare genome: family, kappa, textures and scene are the context's
    std::vector<std::string> warnings;  // each naming the file and field
};

// Reads every JSON that matevo writes for a material:
// - a material file (above);
// - an evolve report (`evolve --json`, result.json): its "best_material";
// - a bare genome ({"eta1": …}) or a population entry ({"genome": {…}, …}), which carries no
//   family: it takes family, kappa, textures and scene from `context`, and is checked against
//   that family.
// Errors name the file and field; texture files must exist.
Result<LoadedMaterial> loadMaterial(const std::filesystem::path& file, const MaterialFile& context);

// The same from text; `folder` resolves relative texture paths (their existence is not checked).
Result<LoadedMaterial> parseMaterial(const std::string& jsonText, const std::string& sourceName,
                                     const std::filesystem::path& folder,
                                     const MaterialFile& context);

}  // namespace matevo
