#include "render/PopulationRenderer.h"

namespace matevo {

Status PopulationRenderer::prepareFor(const EvaluationOptions&) { return Ok{}; }

Result<PopulationEvaluation> PopulationRenderer::evaluateIntoTiles(
    const MaterialInstance& target, std::span<const MaterialInstance> candidates,
    const SceneSettings& scene, int size, const EvaluationOptions& options,
    const TileOutput& tiles) {
    if (tiles.tiles.size() != candidates.size())
        return internalError("render: one tile per candidate expected");
    EvaluationOptions withImages = options;
    withImages.candidateImages = true;  // the tiles' pictures
    auto evaluation = evaluate(target, candidates, scene, size, withImages);
    if (!evaluation) return evaluation.error();
    // A ꟻLIP tile's map holds ꟻLIP where the pixel is pooled and "not covered" elsewhere, so
    // that the window draws either metric's map the same way.
    std::vector<DeltaEMap> flipShown;
    if (options.heatmapMetric == ImageMetric::Flip && !evaluation->flip.empty())
        for (const FlipMap& map : evaluation->flip)
            flipShown.push_back({map.width, map.height, map.error, map.pooled, {}});
    if (Status uploaded = tiles.upload(evaluation->candidates,
                                       flipShown.empty() ? evaluation->deltaE : flipShown);
        !uploaded)
        return uploaded.error();
    if (!options.candidateImages) evaluation->candidates.clear();
    return evaluation;
}

Status PopulationRenderer::renderIntoTile(const MaterialInstance& material,
                                          const SceneSettings& scene, int size,
                                          const TileOutput& tile) {
    auto images = render(std::span(&material, 1), scene, size);
    if (!images) return images.error();
    return tile.upload(*images, {});
}

}  // namespace matevo
