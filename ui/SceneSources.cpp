#include "SceneSources.h"

#include <cstdio>

#include "EditorState.h"

namespace matevo::ui {
namespace {

std::vector<SceneMaterial> populationMaterials(const EditorState& state) {
    std::vector<SceneMaterial> materials;
    for (const CandidateView& candidate : state.evolution.candidates) {
        char label[120];
        std::snprintf(label, sizeof label, "candidate #%d, mean ΔE00 %.2f, fitness %.4f",
                      candidate.rank, candidate.meanDeltaE00, candidate.fitness);
        materials.push_back(
            {materialOf(candidate.genome, state.preset.family, state.preset.baseKappa),
             candidate.genome, label});
    }
    return materials;
}

std::vector<SceneMaterial> keptMaterials(const EditorState& state) {
    std::vector<SceneMaterial> materials;
    for (const KeptMaterial& kept : state.preset.kept)
        materials.push_back({materialOf(kept.genome, kept.family, state.preset.baseKappa),
                             kept.genome, "kept: " + kept.name});
    return materials;
}

}  // namespace

std::vector<SceneMaterial> sceneMaterials(const EditorState& state) {
    switch (state.sceneView.controls.source) {
        case SceneSource::Population: return populationMaterials(state);
        case SceneSource::Variants: return state.sceneView.variantSet;
        case SceneSource::Kept: return keptMaterials(state);
    }
    return {};
}

std::vector<SceneMaterial> variantSceneMaterials(const VariantSet& set, const Preset& preset) {
    const std::vector<double> nearest = set.nearestSibling();
    std::vector<SceneMaterial> materials;
    for (std::size_t i = 0; i < set.variants.size(); ++i) {
        const Variant& variant = set.variants[i];
        char label[120];
        std::snprintf(label, sizeof label,
                      "variant %zu: ΔE00 %.2f to the target, %.2f to the nearest variant", i + 1,
                      variant.deltaEToTarget, nearest[i]);
        materials.push_back(
            {materialOf(variant.genome, preset.family, preset.baseKappa), variant.genome, label});
    }
    return materials;
}

std::string emptySourceNote(SceneSource source) {
    switch (source) {
        case SceneSource::Population: return "No candidates yet: the GA run fills the population";
        case SceneSource::Variants:
            return "No variant set: find one in the Variants window and send it here";
        case SceneSource::Kept: return "The kept bin is empty: keep candidates from the grid";
    }
    return {};
}

}  // namespace matevo::ui
