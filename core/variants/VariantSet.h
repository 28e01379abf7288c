#pragma once
// The set delivered to the user: chosen from the search's archive, rendered at the output
// resolution and checked there. Members are picked farthest-first (each next one the member
// farthest from those already picked), so the set spreads over the band; each is rendered at
// the output size and kept only if it holds there (inside the band, at least minApart from
// every variant kept before it); one that fails is replaced by the next member. With several
// lightings (LightingMeasure.h) every member is rendered under each and must hold under each;
// the images are those of the first lighting.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "common/Image.h"
#include "common/Result.h"
#include "evolve/RenderGenomes.h"
#include "genome/Genome.h"
#include "variants/LightingMeasure.h"
#include "variants/VariantArchive.h"
#include "variants/VariantSearch.h"

namespace matevo {

struct Variant {
    Genome genome;
    Image image;                // at the output size, as the caller's renderer gave it
    double deltaEToTarget = 0;  // mean ΔE00 to the target, at the output size
    bool kept = false;          // the user kept it (VariantRequest::keep)
    // Under each further lighting of the request (after the first, which the two above are
    // of), in order: the mean ΔE00 to the target's render under that lighting.
    std::vector<double> deltaEUnderOthers;

    // The mean ΔE00 to the target under lighting `lighting` (0: the first).
    double deltaEUnder(std::size_t lighting) const;
};

using DistanceMatrix = std::vector<std::vector<double>>;

struct VariantSet {
    Image target;  // under the first lighting
    std::vector<Variant> variants;
    // Mean ΔE00 between variants i and j at the output size, under the first lighting; 0 on the
    // diagonal.
    DistanceMatrix pairwise;
    // The same under each further lighting, in the request's order.
    std::vector<DistanceMatrix> pairwiseUnderOthers;
    // The smallest pairwise distance under any lighting; 0 for fewer than two variants.
    double smallestPairwise = 0;
    std::size_t outputRenders = 0;  // output-size renders spent on checking (one per lighting)
    // The request's lightings the figures are measured under (VariantRequest::lightings).
    std::vector<std::string> lightings;

    const DistanceMatrix& pairwiseUnder(std::size_t lighting) const;
    // For each variant, the distance to its nearest sibling (0 when alone) under `lighting`.
    std::vector<double> nearestSibling(std::size_t lighting = 0) const;
};

// The archive's members in the order chooseVariantSet tries them: pinned members first, then
// farthest-first (the member nearest the band's centre, then again and again the one whose
// nearest already-ordered member is farthest; ties: the earlier one).
std::vector<std::size_t> spreadOrder(const VariantArchive& archive, const DeltaEBand& band);

// The smallest entry off the diagonal of a pairwise matrix; 0 for fewer than two members.
double smallestPairwise(const DistanceMatrix& pairwise);
// For each member of a pairwise matrix, the distance to its nearest other member (0 when alone).
std::vector<double> nearestSiblings(const DistanceMatrix& pairwise);

// outputRender draws at the output size, one render per lighting as for VariantSearch::start;
// give it the images as they will be stored (e.g. quantised as in a PNG) so that the figures
// are the ones found in the files.
Result<VariantSet> chooseVariantSet(const VariantArchive& archive, const VariantRequest& request,
                                    const Genome& target, const LightingRenders& outputRender);

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
