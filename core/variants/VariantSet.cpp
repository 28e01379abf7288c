#include "variants/VariantSet.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "color/LabImage.h"

namespace matevo {
namespace {

// Pinned members first, then farthest-first: the member nearest the band's centre, then again
// and again the one whose nearest already-ordered member is farthest (ties: the earlier one).
std::vector<std::size_t> spreadOrder(const VariantArchive& archive, const DeltaEBand& band) {
    const std::size_t count = archive.size();
    std::vector<std::size_t> order;
    std::vector<bool> taken(count, false);
    for (std::size_t i = 0; i < count; ++i)
        if (archive.members()[i].pinned) {
            order.push_back(i);
            taken[i] = true;
        }
    while (order.size() < count) {
        std::size_t best = count;
        double bestScore = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < count; ++i) {
            if (taken[i]) continue;
            double score;
            if (order.empty()) {
                score = -std::abs(archive.members()[i].deltaEToTarget - band.centre());
            } else {
                score = std::numeric_limits<double>::infinity();
                for (std::size_t j : order) score = std::min(score, archive.distance(i, j));
            }
            if (score > bestScore) {
                bestScore = score;
                best = i;
            }
        }
        order.push_back(best);
        taken[best] = true;
    }
    return order;
}

void updateSmallestPairwise(VariantSet& set) {
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < set.variants.size(); ++i)
        for (std::size_t j = i + 1; j < set.variants.size(); ++j)
            smallest = std::min(smallest, set.pairwise[i][j]);
    set.smallestPairwise = std::isinf(smallest) ? 0.0 : smallest;
}

}  // namespace

std::vector<double> VariantSet::nearestSibling() const {
    std::vector<double> nearest(variants.size(), 0.0);
    for (std::size_t i = 0; i < variants.size(); ++i) {
        double value = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < variants.size(); ++j)
            if (j != i) value = std::min(value, pairwise[i][j]);
        nearest[i] = std::isinf(value) ? 0.0 : value;
    }
    return nearest;
}

Result<VariantSet> chooseVariantSet(const VariantArchive& archive, const VariantRequest& request,
                                    const Genome& target, const RenderGenomes& outputRender) {
    VariantSet set;
    auto targetImages = outputRender(std::span(&target, 1));
    if (!targetImages) return targetImages.error();
    if (targetImages->size() != 1)
        return internalError("the renderer returned no image for the target");
    set.target = std::move(targetImages->front());
    const LabImage targetLab = toLabImage(set.target);

    const std::vector<std::size_t> order = spreadOrder(archive, request.band);
    const auto wanted = std::size_t(std::max(request.count, 0));
    std::vector<LabImage> acceptedLabs;
    std::size_t next = 0;
    while (set.variants.size() < wanted && next < order.size()) {
        // Render as many as are still missing, in one batch.
        const std::size_t batchEnd = std::min(order.size(), next + wanted - set.variants.size());
        std::vector<Genome> genomes;
        for (std::size_t k = next; k < batchEnd; ++k)
            genomes.push_back(archive.members()[order[k]].genome);
        auto images = outputRender(genomes);
        if (!images) return images.error();
        if (images->size() != genomes.size())
            return internalError("the renderer returned " + std::to_string(images->size()) +
                                 " images for " + std::to_string(genomes.size()) + " genomes");
        set.outputRenders += genomes.size();
        for (std::size_t k = 0; k < genomes.size() && set.variants.size() < wanted; ++k) {
            const ArchivedVariant& member = archive.members()[order[next + k]];
            LabImage lab = toLabImage((*images)[k]);
            const double deltaE = meanDeltaE00(targetLab, lab);
            std::vector<double> distances;
            bool apart = true;
            for (const LabImage& other : acceptedLabs) {
                distances.push_back(meanDeltaE00(lab, other));
                apart = apart && distances.back() >= request.minApart;
            }
            if (!member.pinned && !(request.band.contains(deltaE) && apart)) continue;
            for (std::size_t i = 0; i < distances.size(); ++i) set.pairwise[i].push_back(distances[i]);
            distances.push_back(0.0);
            set.pairwise.push_back(std::move(distances));
            set.variants.push_back({member.genome, std::move((*images)[k]), deltaE, member.pinned});
            acceptedLabs.push_back(std::move(lab));
        }
        next = batchEnd;
    }
    updateSmallestPairwise(set);
    return set;
}

void removeVariant(VariantSet& set, std::size_t index) {
    if (index >= set.variants.size()) return;
    const auto offset = std::ptrdiff_t(index);
    set.variants.erase(set.variants.begin() + offset);
    set.pairwise.erase(set.pairwise.begin() + offset);
    for (auto& row : set.pairwise) row.erase(row.begin() + offset);
    updateSmallestPairwise(set);
}

bool fulfils(const VariantSet& set, const VariantRequest& request) {
    return set.variants.size() >= std::size_t(std::max(request.count, 0));
}

}  // namespace matevo
