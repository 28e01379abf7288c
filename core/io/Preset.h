#pragma once
// A preset: everything needed to reproduce a run — the target material, its family, the
// conductor base's fixed extinction kappa, the GA settings and the scene.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "common/Result.h"
#include "evolve/GaSettings.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"
#include "scene/SceneSettings.h"

namespace matevo {

struct Preset {
    std::string name = "untitled";
    std::string description;
    MaterialFamily family;
    Genome target;
    // Extinction coefficient of a conductor base (RGB). The genotype has no kappa, so it is the
    // metal's fixed identity (docs/architecture.md, "Decisions"); ignored for a dielectric base.
    std::array<double, 3> baseKappa = {0.0, 0.0, 0.0};
    // Texture files relative to the preset's folder; empty when unused.
    std::string roughnessTexture;  // for the textured layer of the family
    std::string baseColorTexture;  // tints the base layer
    GaSettings ga;
    SceneSettings scene;

    bool operator==(const Preset&) const = default;
};

struct LoadedPreset {
    Preset preset;
    std::vector<std::string> warnings;  // e.g. unknown fields, each naming file and field
};

// Errors name the file and the JSON field ("my-preset.json: ga.population: must be in [2,
// 100000], got 0").
Result<LoadedPreset> loadPreset(const std::filesystem::path& file);
Result<LoadedPreset> parsePreset(const std::string& jsonText, const std::string& sourceName);
std::string serializePreset(const Preset& preset);
// Atomic: written to a temporary file beside the target, then renamed over it.
Status savePreset(const Preset& preset, const std::filesystem::path& file);

}  // namespace matevo
