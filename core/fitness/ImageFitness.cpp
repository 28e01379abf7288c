#include "fitness/ImageFitness.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace matevo {

ImageSpaceFitness::ImageSpaceFitness(GenomeRenderCache cache, DeltaEBand band)
    : cache_(std::move(cache)), band_(band) {}

FitnessEvaluator ImageSpaceFitness::evaluator() {
    return [this](std::span<const Genome> genomes, std::span<double> fitness) {
        score(genomes, fitness);
    };
}

void ImageSpaceFitness::score(std::span<const Genome> genomes, std::span<double> fitness) {
    if (!failure_)
        if (auto rendered = cache_.renderMissing(genomes); !rendered) failure_ = rendered.error();
    if (failure_) {
        std::fill(fitness.begin(), fitness.end(), std::numeric_limits<double>::infinity());
        return;
    }
    const bool flip = cache_.metric() == ImageMetric::Flip;
    for (std::size_t i = 0; i < genomes.size(); ++i) {
        const GenomeRender& render = cache_.at(genomes[i]);
        fitness[i] = band_.violation(flip ? render.flipToTarget : render.deltaEToTarget);
    }
    cache_.forgetAllBut(genomes);
}

}  // namespace matevo
