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
    const auto shown = evaluation->errors.find(options.heatmapMetric);
    const std::vector<ErrorMap>& maps = shown != evaluation->errors.end()
                                            ? shown->second
                                            : evaluation->errors.at(ImageMetric::DeltaE00);
    if (Status uploaded = tiles.upload(evaluation->candidates, maps); !uploaded)
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
