#pragma once
// The image-space fitness for the GA (beside the paper's genotype distances): a genome's
// rendered mean ΔE00 (or, with a cache made for ꟻLIP, mean ꟻLIP) from the target over the
// sphere's pixels (the rule of `matevo compare`), or, with a band, how far outside the band
// that lies — 0 inside, where the objective is met.
// A whole generation is rendered in one batch through the cache, so a genome that recurs (a
// parent copied unchanged) is not rendered again. Only the latest generation's renders are
// kept, which bounds the memory of a long run.
#include <optional>

#include "common/Result.h"
#include "evolve/GeneticAlgorithm.h"
#include "fitness/DeltaEBand.h"
#include "fitness/GenomeRenderCache.h"

namespace matevo {

class ImageSpaceFitness {
public:
    // band {0, 0}: the plain mean (lower is fitter). The band is in the cache's metric.
    ImageSpaceFitness(GenomeRenderCache cache, DeltaEBand band = {0.0, 0.0});
    ImageSpaceFitness(const ImageSpaceFitness&) = delete;
    ImageSpaceFitness& operator=(const ImageSpaceFitness&) = delete;

    // For GeneticAlgorithm; refers to this object, which must outlive the GA. When a render
    // fails every fitness is +infinity from then on and failure() says why.
    FitnessEvaluator evaluator();
    const std::optional<Error>& failure() const { return failure_; }
    // Mean ΔE00 to the target of a genome of the latest scored generation.
    double deltaEToTarget(const Genome& genome) const { return cache_.at(genome).deltaEToTarget; }
    std::size_t renderCount() const { return cache_.renderCount(); }

private:
    void score(std::span<const Genome> genomes, std::span<double> fitness);

    GenomeRenderCache cache_;
    DeltaEBand band_;
    std::optional<Error> failure_;
};

}  // namespace matevo
