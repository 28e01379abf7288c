#pragma once
// The variant search's renders under every lighting it must hold under (LightingMeasure.h):
// one GenomeRenderCache per lighting, each with the target rendered under that lighting, so a
// genome's ΔE00 to the target is measured lighting by lighting. A genome is rendered under all
// of them or none.
#include <cstddef>
#include <span>
#include <vector>

#include "common/Result.h"
#include "fitness/GenomeRenderCache.h"
#include "genome/Genome.h"
#include "variants/LightingMeasure.h"

namespace matevo {

class LightingRenderCache {
public:
    static Result<LightingRenderCache> create(const LightingRenders& renders, const Genome& target);

    // Renders, one batch per lighting, each genome that is not held yet.
    Status renderMissing(std::span<const Genome> genomes);
    bool contains(const Genome& genome) const { return caches_.front().contains(genome); }
    // The genome must be held (renderMissing first). Its mean ΔE00 to the target and its
    // renders, per lighting.
    std::vector<double> deltaEsToTarget(const Genome& genome) const;
    LabsPerLighting labs(const Genome& genome) const;

    void forgetAllBut(std::span<const Genome> keep);
    // Genomes rendered so far (each under every lighting): the evaluations a search has used.
    std::size_t renderCount() const { return caches_.front().renderCount(); }

private:
    explicit LightingRenderCache(std::vector<GenomeRenderCache> caches)
        : caches_(std::move(caches)) {}

    std::vector<GenomeRenderCache> caches_;  // never empty
};

}  // namespace matevo
