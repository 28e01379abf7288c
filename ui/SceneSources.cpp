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

// The document's set, in the family and kappa it was made for; the Variants window's tiles,
// when they show that set, give the labels their distances.
std::vector<SceneMaterial> variantMaterials(const EditorState& state) {
    std::vector<SceneMaterial> materials;
    if (!state.preset.variantSet) return materials;
    const SavedVariantSet& set = *state.preset.variantSet;
    const std::vector<VariantTileView>& tiles = state.variants.variants;
    for (std::size_t i = 0; i < set.variants.size(); ++i) {
        char label[120];
        if (i < tiles.size() && tiles[i].genome == set.variants[i])
            std::snprintf(label, sizeof label,
                          "variant %zu: ΔE00 %.2f to the target, %.2f to the nearest variant",
                          i + 1, tiles[i].deltaEToTarget, tiles[i].nearestSibling);
        else
            std::snprintf(label, sizeof label, "variant %zu", i + 1);
        materials.push_back(
            {materialOf(set.variants[i], set.family, set.baseKappa), set.variants[i], label});
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
        case SceneSource::Population:
            return populationMaterials(state);
        case SceneSource::Variants:
            return variantMaterials(state);
        case SceneSource::Kept:
            return keptMaterials(state);
    }
    return {};
}

std::string emptySourceNote(SceneSource source) {
    switch (source) {
        case SceneSource::Population:
            return "No candidates yet: the GA run fills the population";
        case SceneSource::Variants:
            return "No variant set: find one in the Variants window";
        case SceneSource::Kept:
            return "The kept bin is empty: keep candidates from the grid";
    }
    return {};
}

}  // namespace matevo::ui
