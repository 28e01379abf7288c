#pragma once
// Renders of genomes at one size, made once per genome and kept as L*a*b* with the mean ΔE00
// to the target's render (the rule of compareImages) and, in a cache made for ꟻLIP, the mean
// ꟻLIP (computeFlip). Genomes are rendered in batches, so a GPU
// renderer draws a whole population in one submission; a genome already held is not rendered
// again. forgetAllBut() bounds the memory of a long search.
#include <cstddef>
#include <span>
#include <unordered_map>

#include "color/ImageMetric.h"
#include "color/LabImage.h"
#include "common/Result.h"
#include "evolve/RenderGenomes.h"
#include "genome/Genome.h"

namespace matevo {

struct GenomeRender {
    LabImage lab;
    double deltaEToTarget = 0;
    double flipToTarget = 0;  // only in a cache made for ImageMetric::Flip
};

// Bit-pattern hash; -0 and +0 hash alike, as they compare equal.
struct GenomeHash {
    std::size_t operator()(const Genome& genome) const;
};

class GenomeRenderCache {
public:
    // Renders the target once; its render is what every genome is compared with. `metric` Flip
    // also scores each genome by mean ꟻLIP (and keeps the target's linear render for it).
    static Result<GenomeRenderCache> create(RenderGenomes render, const Genome& target,
                                            ImageMetric metric = ImageMetric::DeltaE00);

    // Renders, in one batch, each genome that is not held yet (a repeated one once).
    Status renderMissing(std::span<const Genome> genomes);
    // The genome must be held (renderMissing first).
    const GenomeRender& at(const Genome& genome) const { return renders_.at(genome); }
    bool contains(const Genome& genome) const { return renders_.contains(genome); }

    // Drops every render but those of `keep`; a dropped genome is rendered again when asked for.
    void forgetAllBut(std::span<const Genome> keep);

    const LabImage& target() const { return target_; }
    ImageMetric metric() const { return metric_; }
    // Genomes rendered so far (the target not counted): the evaluations a search has used.
    std::size_t renderCount() const { return renderCount_; }

private:
    RenderGenomes render_;
    LabImage target_;
    ImageMetric metric_ = ImageMetric::DeltaE00;
    Image targetImage_;  // linear, for ꟻLIP; empty otherwise
    std::unordered_map<Genome, GenomeRender, GenomeHash> renders_;
    std::size_t renderCount_ = 0;
};

}  // namespace matevo
