#include "variants/VariantSet.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "color/LabImage.h"

namespace matevo {

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
                score = -offCentre(band, archive.members()[i].deltaEToTarget);
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

double smallestPairwise(const DistanceMatrix& pairwise) {
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < pairwise.size(); ++i)
        for (std::size_t j = i + 1; j < pairwise.size(); ++j)
            smallest = std::min(smallest, pairwise[i][j]);
    return std::isinf(smallest) ? 0.0 : smallest;
}

std::vector<double> nearestSiblings(const DistanceMatrix& pairwise) {
    std::vector<double> nearest(pairwise.size(), 0.0);
    for (std::size_t i = 0; i < pairwise.size(); ++i) {
        double value = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < pairwise.size(); ++j)
            if (j != i) value = std::min(value, pairwise[i][j]);
        nearest[i] = std::isinf(value) ? 0.0 : value;
    }
    return nearest;
}

namespace {

// The smallest pairwise distance under any of the set's lightings.
void updateSmallestPairwise(VariantSet& set) {
    double smallest = smallestPairwise(set.pairwise);
    for (const DistanceMatrix& matrix : set.pairwiseUnderOthers)
        smallest = std::min(smallest, smallestPairwise(matrix));
    set.smallestPairwise = smallest;
}

// Images of a batch of genomes under one lighting, checked to be one per genome.
Result<std::vector<Image>> renderBatch(const RenderGenomes& render,
                                       std::span<const Genome> genomes) {
    auto images = render(genomes);
    if (!images) return images.error();
    if (images->size() != genomes.size())
        return internalError("the renderer returned " + std::to_string(images->size()) +
                             " images for " + std::to_string(genomes.size()) + " genomes");
    return images;
}

// Adds a row and column of distances (to the members before it) to a matrix.
void addToMatrix(DistanceMatrix& matrix, std::vector<double> distances) {
    for (std::size_t i = 0; i < distances.size(); ++i) matrix[i].push_back(distances[i]);
    distances.push_back(0.0);
    matrix.push_back(std::move(distances));
}

void removeFromMatrix(DistanceMatrix& matrix, std::size_t index) {
    const auto offset = std::ptrdiff_t(index);
    matrix.erase(matrix.begin() + offset);
    for (auto& row : matrix) row.erase(row.begin() + offset);
}

}  // namespace

double Variant::deltaEUnder(std::size_t lighting) const {
    return lighting == 0 ? deltaEToTarget : deltaEUnderOthers.at(lighting - 1);
}

const DistanceMatrix& VariantSet::pairwiseUnder(std::size_t lighting) const {
    return lighting == 0 ? pairwise : pairwiseUnderOthers.at(lighting - 1);
}

std::vector<double> VariantSet::nearestSibling(std::size_t lighting) const {
    return nearestSiblings(pairwiseUnder(lighting));
}

Result<VariantSet> chooseVariantSet(const VariantArchive& archive, const VariantRequest& request,
                                    const Genome& target, const LightingRenders& outputRender) {
    const std::size_t lightings = outputRender.count();
    if (lightings == 0) return internalError("a variant set needs at least one lighting");
    VariantSet set;
    set.lightings = request.lightings;
    set.pairwiseUnderOthers.resize(lightings - 1);
    LabsPerLighting targetLabs;
    for (const RenderGenomes& render : outputRender.perLighting) {
        auto targetImages = renderBatch(render, std::span(&target, 1));
        if (!targetImages) return targetImages.error();
        targetLabs.push_back(toLabImage(targetImages->front()));
        if (set.target.width == 0) set.target = std::move(targetImages->front());
    }

    const std::vector<std::size_t> order = spreadOrder(archive, request.band);
    const auto wanted = std::size_t(std::max(request.count, 0));
    std::vector<LabsPerLighting> acceptedLabs;
    std::size_t next = 0;
    while (set.variants.size() < wanted && next < order.size()) {
        // Render as many as are still missing, in one batch per lighting.
        const std::size_t batchEnd = std::min(order.size(), next + wanted - set.variants.size());
        std::vector<Genome> genomes;
        for (std::size_t k = next; k < batchEnd; ++k)
            genomes.push_back(archive.members()[order[k]].genome);
        std::vector<std::vector<Image>> images;  // per lighting, per genome
        for (const RenderGenomes& render : outputRender.perLighting) {
            auto batch = renderBatch(render, genomes);
            if (!batch) return batch.error();
            images.push_back(std::move(batch).value());
        }
        set.outputRenders += genomes.size() * lightings;
        for (std::size_t k = 0; k < genomes.size() && set.variants.size() < wanted; ++k) {
            const ArchivedVariant& member = archive.members()[order[next + k]];
            LabsPerLighting labs;
            for (const auto& batch : images) labs.push_back(toLabImage(batch[k]));
            const std::vector<double> deltaEs = deltaEPerLighting(targetLabs, labs);
            // distances[l][i]: to accepted variant i under lighting l.
            std::vector<std::vector<double>> distances(lightings);
            bool apart = true;
            for (const LabsPerLighting& other : acceptedLabs) {
                const std::vector<double> perLighting = deltaEPerLighting(labs, other);
                for (std::size_t l = 0; l < lightings; ++l) {
                    distances[l].push_back(perLighting[l]);
                    apart = apart && perLighting[l] >= request.minApart;
                }
            }
            if (!member.pinned && !(inBandUnderEvery(request.band, deltaEs) && apart)) continue;
            addToMatrix(set.pairwise, std::move(distances[0]));
            for (std::size_t l = 1; l < lightings; ++l)
                addToMatrix(set.pairwiseUnderOthers[l - 1], std::move(distances[l]));
            set.variants.push_back({member.genome, std::move(images[0][k]), deltaEs[0],
                                    member.pinned,
                                    std::vector<double>(deltaEs.begin() + 1, deltaEs.end())});
            acceptedLabs.push_back(std::move(labs));
        }
        next = batchEnd;
    }
    updateSmallestPairwise(set);
    return set;
}

Result<VariantSet> measureVariantSet(const Genome& target, std::span<const Genome> genomes,
                                     const RenderGenomes& outputRender) {
    std::vector<Genome> all{target};
    all.insert(all.end(), genomes.begin(), genomes.end());
    auto images = outputRender(all);
    if (!images) return images.error();
    if (images->size() != all.size())
        return internalError("the renderer returned " + std::to_string(images->size()) +
                             " images for " + std::to_string(all.size()) + " genomes");
    std::vector<LabImage> labs;
    for (const Image& image : *images) labs.push_back(toLabImage(image));
    VariantSet set;
    set.target = std::move(images->front());
    set.outputRenders = genomes.size();
    const std::size_t count = genomes.size();
    set.pairwise.assign(count, std::vector<double>(count, 0.0));
    for (std::size_t i = 0; i < count; ++i) {
        set.variants.push_back({genomes[i],
                                std::move((*images)[i + 1]),
                                meanDeltaE00(labs[0], labs[i + 1]),
                                false,
                                {}});
        for (std::size_t j = 0; j < i; ++j)
            set.pairwise[i][j] = set.pairwise[j][i] = meanDeltaE00(labs[i + 1], labs[j + 1]);
    }
    updateSmallestPairwise(set);
    return set;
}

void removeVariant(VariantSet& set, std::size_t index) {
    if (index >= set.variants.size()) return;
    set.variants.erase(set.variants.begin() + std::ptrdiff_t(index));
    removeFromMatrix(set.pairwise, index);
    for (DistanceMatrix& matrix : set.pairwiseUnderOthers) removeFromMatrix(matrix, index);
    updateSmallestPairwise(set);
}

bool fulfils(const VariantSet& set, const VariantRequest& request) {
    return set.variants.size() >= std::size_t(std::max(request.count, 0));
}

}  // namespace matevo
