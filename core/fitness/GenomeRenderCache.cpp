#include "fitness/GenomeRenderCache.h"

#include <bit>
#include <cstdint>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "color/Flip.h"

namespace matevo {

std::size_t GenomeHash::operator()(const Genome& genome) const {
    std::uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a over the values' bits
    for (double value : genome.values) {
        hash ^= std::bit_cast<std::uint64_t>(value + 0.0);  // + 0.0 turns -0 into +0
        hash *= 0x100000001b3ULL;
    }
    return std::size_t(hash);
}

Result<GenomeRenderCache> GenomeRenderCache::create(RenderGenomes render, const Genome& target,
                                                    ImageMetric metric) {
    auto images = render(std::span(&target, 1));
    if (!images) return images.error();
    if (images->size() != 1) return internalError("the renderer returned no image for the target");
    GenomeRenderCache cache;
    cache.render_ = std::move(render);
    cache.target_ = toLabImage(images->front());
    cache.metric_ = metric;
    if (metric == ImageMetric::Flip) cache.targetImage_ = std::move(images->front());
    return cache;
}

Status GenomeRenderCache::renderMissing(std::span<const Genome> genomes) {
    std::vector<Genome> missing;
    std::unordered_set<Genome, GenomeHash> queued;
    for (const Genome& genome : genomes)
        if (!renders_.contains(genome) && queued.insert(genome).second) missing.push_back(genome);
    if (missing.empty()) return Ok{};
    auto images = render_(missing);
    if (!images) return images.error();
    if (images->size() != missing.size())
        return internalError("the renderer returned " + std::to_string(images->size()) +
                             " images for " + std::to_string(missing.size()) + " genomes");
    for (std::size_t i = 0; i < missing.size(); ++i) {
        GenomeRender entry{toLabImage((*images)[i]), 0.0};
        entry.deltaEToTarget = meanDeltaE00(target_, entry.lab);
        if (metric_ == ImageMetric::Flip) {
            auto flip = computeFlip(targetImage_, (*images)[i]);
            if (!flip) return flip.error();
            entry.flipToTarget = flip->stats.mean;
        }
        renders_.emplace(missing[i], std::move(entry));
    }
    renderCount_ += missing.size();
    return Ok{};
}

void GenomeRenderCache::forgetAllBut(std::span<const Genome> keep) {
    const std::unordered_set<Genome, GenomeHash> kept(keep.begin(), keep.end());
    std::erase_if(renders_, [&](const auto& entry) { return !kept.contains(entry.first); });
}

}  // namespace matevo
