#pragma once
// The set delivered to the user: chosen from the search's archive, rendered at the output
// resolution and checked there. Members are picked farthest-first (each next one the member
// farthest from those already picked), so the set spreads over the band; each is rendered at
// the output size and kept only if it holds there (inside the band, at least minApart from
// every variant kept before it); one that fails is replaced by the next member.
#include <cstddef>
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

// The archive's members in the order chooseVariantSet tries them: pinned members first, then
// farthest-first (the member nearest the band's centre, then again and again the one whose
// nearest already-ordered member is farthest; ties: the earlier one).
std::vector<std::size_t> spreadOrder(const VariantArchive& archive, const DeltaEBand& band);

// The smallest entry off the diagonal of a pairwise matrix; 0 for fewer than two members.
double smallestPairwise(const std::vector<std::vector<double>>& pairwise);
// For each member of a pairwise matrix, the distance to its nearest other member (0 when alone).
std::vector<double> nearestSiblings(const std::vector<std::vector<double>>& pairwise);

// outputRender draws at the output size; give it the images as they will be stored (e.g.
// quantised as in a PNG) so that the figures are the ones found in the files.
Result<VariantSet> chooseVariantSet(const VariantArchive& archive, const VariantRequest& request,
                                    const Genome& target, const RenderGenomes& outputRender);

// Drops variant `index` (the user discarded it), keeping the matrix and smallest distance right.
void removeVariant(VariantSet& set, std::size_t index);

// Every variant asked for is there (all are inside the band and minApart apart by construction).
bool fulfils(const VariantSet& set, const VariantRequest& request);

}  // namespace matevo
