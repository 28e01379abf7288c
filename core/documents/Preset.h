#pragma once
// A preset: everything needed to reproduce a run — the target material, its family, the
// conductor base's fixed extinction kappa, the GA settings and the scene.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/Result.h"
#include "evolve/GaSettings.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"
#include "scene/SceneSettings.h"

namespace matevo {

// A material the user kept from a run ("the kept bin"): a name and a genome. Kept materials
// outlive re-runs, seeds and family changes, so a genome need not fit the preset's current
// family; it is what variant sets and exports start from.
struct KeptMaterial {
    std::string name;
    Genome genome;
    MaterialFamily family;  // the family it was evolved in

    bool operator==(const KeptMaterial&) const = default;
};

// The editor's working variant set, saved with the document as "variant_set": its members in
// order and the target they were measured against, so that a reopened document shows the same
// set and can say when the target has changed under it. The measurements (ΔE00, pairwise) are
// made again from the genomes.
struct SavedVariantSet {
    MaterialFamily family;  // the family and target the set was made for
    Genome target;
    std::array<double, 3> baseKappa = {0.0, 0.0, 0.0};
    std::vector<Genome> variants;  // kappa genes included (hue variety)

    bool operator==(const SavedVariantSet&) const = default;
};

// The preset format this matevo writes ("format_version"). 1: no version field, every field
// written. 2: only what differs from the defaults of GaSettings, SceneSettings, MaterialFamily
// and Genome (the defaults of format 2; a change of a default is a new format), and a scene
// field given without scene.mode means what it says. Both are read.
inline constexpr int kPresetFormatVersion = 2;

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
    // Beyond the paper: the GA ranks by each candidate's rendered mean ΔE00 from the target
    // (the editor's "Image ΔE00" metric) instead of ga.metric; saved as "fitness": "image".
    bool imageFitness = false;
    SceneSettings scene;
    std::vector<KeptMaterial> kept;  // saved as "kept": [{"name", "family", "genome"}, …]
    std::optional<SavedVariantSet> variantSet;

    bool operator==(const Preset&) const = default;
};

// The genomes of the kept materials evolved in the preset's current family, in the bin's
// order: what the editor draws beside a run and what a variant set starts from.
std::vector<Genome> keptGenomesOfFamily(const Preset& preset);

// The saved set was made for another target than the preset's present one (or family, kappa).
bool variantSetMadeForAnotherTarget(const Preset& preset);

struct LoadedPreset {
    Preset preset;
    std::vector<std::string> warnings;  // e.g. unknown fields, each naming file and field
};

// Errors name the file and the JSON field ("my-preset.json: ga.population: must be in [2,
// 100000], got 0").
Result<LoadedPreset> loadPreset(const std::filesystem::path& file);
Result<LoadedPreset> parsePreset(const std::string& jsonText, const std::string& sourceName);
// Minimal and ordered: the format version, then the fields a person reads first (name, family,
// target), and of the rest only what differs from the defaults (see kPresetFormatVersion).
std::string serializePreset(const Preset& preset);
// Atomic: written to a temporary file beside the target, then renamed over it.
Status savePreset(const Preset& preset, const std::filesystem::path& file);

}  // namespace matevo
