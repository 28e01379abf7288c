#include "variants/ImageFitness.h"

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
    for (std::size_t i = 0; i < genomes.size(); ++i)
        fitness[i] = band_.violation(cache_.at(genomes[i]).deltaEToTarget);
    cache_.forgetAllBut(genomes);
}

}  // namespace matevo
