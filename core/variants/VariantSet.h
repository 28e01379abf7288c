#pragma once
// The set delivered to the user: chosen from the search's archive, rendered at the output
// resolution and checked there. Members are picked farthest-first (each next one the member
// farthest from those already picked), so the set spreads over the band; each is rendered at
// the output size and kept only if it holds there (inside the band, at least minApart from
// every variant kept before it); one that fails is replaced by the next member.
#include <cstddef>
#include <span>
#include <vector>

#include "common/Image.h"
#include "common/Result.h"
#include "evolve/RenderGenomes.h"
#include "genome/Genome.h"
#include "variants/VariantArchive.h"
#include "variants/VariantSearch.h"

namespace matevo {

struct Variant {
    Genome genome;
    Image image;                // at the output size, as the caller's renderer gave it
    double deltaEToTarget = 0;  // mean ΔE00 to the target, at the output size
    bool kept = false;          // the user kept it (VariantRequest::keep)
};

struct VariantSet {
    Image target;
    std::vector<Variant> variants;
    // Mean ΔE00 between variants i and j at the output size; 0 on the diagonal.
    std::vector<std::vector<double>> pairwise;
    // The smallest pairwise distance; 0 for fewer than two variants.
    double smallestPairwise = 0;
    std::size_t outputRenders = 0;  // output-size renders spent on checking

    // For each variant, the distance to its nearest sibling (0 when alone).
    std::vector<double> nearestSibling() const;
};

// outputRender draws at the output size; give it the images as they will be stored (e.g.
// quantised as in a PNG) so that the figures are the ones found in the files.
Result<VariantSet> chooseVariantSet(const VariantArchive& archive, const VariantRequest& request,
                                    const Genome& target, const RenderGenomes& outputRender);

// Exactly these genomes, in this order, rendered at the output size and measured against the
// target (ΔE00 to it and pairwise): a saved set shown again, or a set re-measured after its
// target changed. Nothing is dropped, whether or not it is still inside a band.
Result<VariantSet> measureVariantSet(const Genome& target, std::span<const Genome> genomes,
                                     const RenderGenomes& outputRender);

// Drops variant `index` (the user discarded it), keeping the matrix and smallest distance right.
void removeVariant(VariantSet& set, std::size_t index);

// Every variant asked for is there (all are inside the band and minApart apart by construction).
bool fulfils(const VariantSet& set, const VariantRequest& request);

}  // namespace matevo
