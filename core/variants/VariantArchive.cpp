#include "variants/VariantArchive.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace matevo {

std::vector<double> VariantArchive::distancesTo(const LabsPerLighting& labs) const {
    std::vector<double> distances;
    distances.reserve(members_.size());
    for (const ArchivedVariant& member : members_)
        distances.push_back(apartUnderEvery(labs, member.labs));
    return distances;
}

bool VariantArchive::offer(const Genome& genome, LabsPerLighting labs,
                           std::vector<double> deltaEToTarget,
                           const std::vector<double>& distances) {
    std::size_t closeCount = 0;
    std::size_t closeMember = 0;
    for (std::size_t i = 0; i < members_.size(); ++i) {
        if (members_[i].genome == genome) return false;
        if (distances[i] < minApart_) {
            ++closeCount;
            closeMember = i;
        }
    }
    if (closeCount == 0) {
        add(genome, std::move(labs), std::move(deltaEToTarget), false, distances);
        return true;
    }
    if (closeCount > 1 || members_[closeMember].pinned) return false;
    // Local competition: the newcomer takes the member's niche if it has more room around it
    // among the other members. Every other member is at least minApart from it (only one was
    // closer), so the archive stays valid.
    double newcomerRoom = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < members_.size(); ++i)
        if (i != closeMember) newcomerRoom = std::min(newcomerRoom, distances[i]);
    if (newcomerRoom <= room(closeMember, closeMember)) return false;
    members_[closeMember] = {nextId_++, genome, std::move(labs), std::move(deltaEToTarget), false};
    for (std::size_t i = 0; i < members_.size(); ++i) {
        const double d = i == closeMember ? 0.0 : distances[i];
        distances_[closeMember][i] = d;
        distances_[i][closeMember] = d;
    }
    return true;
}

void VariantArchive::pin(const Genome& genome, LabsPerLighting labs,
                         std::vector<double> deltaEToTarget) {
    std::vector<double> distances = distancesTo(labs);
    add(genome, std::move(labs), std::move(deltaEToTarget), true, std::move(distances));
}

bool VariantArchive::holds(std::uint64_t id) const {
    return std::any_of(members_.begin(), members_.end(),
                       [id](const ArchivedVariant& member) { return member.id == id; });
}

void VariantArchive::add(const Genome& genome, LabsPerLighting labs,
                         std::vector<double> deltaEToTarget, bool pinned,
                         std::vector<double> distances) {
    for (std::size_t i = 0; i < members_.size(); ++i) distances_[i].push_back(distances[i]);
    distances.push_back(0.0);
    distances_.push_back(std::move(distances));
    members_.push_back({nextId_++, genome, std::move(labs), std::move(deltaEToTarget), pinned});
}

double VariantArchive::room(std::size_t i, std::size_t skip) const {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < members_.size(); ++j)
        if (j != i && j != skip) nearest = std::min(nearest, distances_[i][j]);
    return nearest;
}

}  // namespace matevo
