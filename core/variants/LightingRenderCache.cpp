#include "variants/LightingRenderCache.h"

#include <utility>

namespace matevo {

Result<LightingRenderCache> LightingRenderCache::create(const LightingRenders& renders,
                                                        const Genome& target) {
    if (renders.count() == 0) return internalError("a variant search needs at least one lighting");
    std::vector<GenomeRenderCache> caches;
    for (const RenderGenomes& render : renders.perLighting) {
        auto cache = GenomeRenderCache::create(render, target);
        if (!cache) return cache.error();
        caches.push_back(std::move(cache).value());
    }
    return LightingRenderCache(std::move(caches));
}

Status LightingRenderCache::renderMissing(std::span<const Genome> genomes) {
    for (GenomeRenderCache& cache : caches_)
        if (auto rendered = cache.renderMissing(genomes); !rendered) return rendered;
    return Ok{};
}

std::vector<double> LightingRenderCache::deltaEsToTarget(const Genome& genome) const {
    std::vector<double> deltaEs;
    deltaEs.reserve(caches_.size());
    for (const GenomeRenderCache& cache : caches_)
        deltaEs.push_back(cache.at(genome).deltaEToTarget);
    return deltaEs;
}

LabsPerLighting LightingRenderCache::labs(const Genome& genome) const {
    LabsPerLighting labs;
    labs.reserve(caches_.size());
    for (const GenomeRenderCache& cache : caches_) labs.push_back(cache.at(genome).lab);
    return labs;
}

void LightingRenderCache::forgetAllBut(std::span<const Genome> keep) {
    for (GenomeRenderCache& cache : caches_) cache.forgetAllBut(keep);
}

}  // namespace matevo
