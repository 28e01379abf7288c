#pragma once
// The quality-diversity archive of the variant search: renders inside the band, every two of
// them at least `minApart` mean ΔE00 apart, so the archive never holds duplicates or near-twins.
// It is unstructured (Cully & Demiris 2018): a niche is "everything closer than minApart to a
// member", measured on the renders themselves rather than on hand-chosen descriptors as in
// MAP-Elites' grid. A newcomer joins when it is far enough from every member; one that falls
// inside a single member's niche competes with it locally (as in MAP-Elites, but on novelty):
// it takes the member's place when it lies farther from the rest of the archive, so the archive
// spreads out over the band as the search goes on. With several lightings (LightingMeasure.h)
// each member holds its render under every one, and "apart" means apart under every one.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "genome/Genome.h"
#include "variants/LightingMeasure.h"

namespace matevo {

struct ArchivedVariant {
    std::uint64_t id = 0;  // unique over the archive's life: a newcomer always has a higher one
    Genome genome;
    LabsPerLighting labs;
    std::vector<double> deltaEToTarget;  // per lighting
    bool pinned = false;                 // kept by the user: never replaced
};

class VariantArchive {
public:
    explicit VariantArchive(double minApart) : minApart_(minApart) {}

    // The spacing under every lighting (apartUnderEvery) from labs to every member, in member
    // order.
    std::vector<double> distancesTo(const LabsPerLighting& labs) const;
    // Adds renders the caller has checked to be inside the band under every lighting;
    // `distances` are distancesTo(labs). Returns whether the archive changed (joined, or
    // replaced a member).
    bool offer(const Genome& genome, LabsPerLighting labs, std::vector<double> deltaEToTarget,
               const std::vector<double>& distances);
    // A variant the user keeps: joins unconditionally (even closer than minApart to another
    // pinned one) and is never replaced.
    void pin(const Genome& genome, LabsPerLighting labs, std::vector<double> deltaEToTarget);

    // Whether a member with this id is still in the archive.
    bool holds(std::uint64_t id) const;
    std::uint64_t lastId() const { return nextId_ - 1; }

    const std::vector<ArchivedVariant>& members() const { return members_; }
    // The spacing under every lighting between members i and j (fitness resolution).
    double distance(std::size_t i, std::size_t j) const { return distances_[i][j]; }
    std::size_t size() const { return members_.size(); }
    double minApart() const { return minApart_; }

private:
    void add(const Genome& genome, LabsPerLighting labs, std::vector<double> deltaEToTarget,
             bool pinned, std::vector<double> distances);
    // Distance from member i to its nearest other member, skipping member `skip`.
    double room(std::size_t i, std::size_t skip) const;

    double minApart_;
    std::uint64_t nextId_ = 1;
    std::vector<ArchivedVariant> members_;
    std::vector<std::vector<double>> distances_;  // symmetric, 0 on the diagonal
};

}  // namespace matevo
