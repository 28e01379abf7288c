#include "variants/DeliveryCheck.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "color/LabImage.h"

namespace matevo {
namespace {

// One image per genome, or an Error saying what came back instead.
Result<std::vector<Image>> checkedImages(Result<std::vector<Image>> images, std::size_t wanted,
                                         const std::string& what) {
    if (!images) return images.error();
    if (images->size() != wanted)
        return internalError(what + " returned " + std::to_string(images->size()) + " images for " +
                             std::to_string(wanted) + " genomes");
    return images;
}

void appendToPairwise(std::vector<std::vector<double>>& pairwise, std::vector<double> distances) {
    for (std::size_t i = 0; i < distances.size(); ++i) pairwise[i].push_back(distances[i]);
    distances.push_back(0.0);
    pairwise.push_back(std::move(distances));
}

// The greedy check: candidates are offered in order, each accepted when it holds on both
// renders against the target and every variant accepted before it.
class DeliveryChecker {
public:
    DeliveryChecker(const VariantRequest& request, const DeliveryFormat& format)
        : request_(request), format_(format) {}

    Status start(Image belcourTarget, const Genome& target) {
        auto look = checkedImages(format_.render(std::span(&target, 1), 0), 1, format_.name);
        if (!look) return look.error();
        ++result_.delivered.conversions;
        belcourTargetLab_ = toLabImage(belcourTarget);
        deliveredTargetLab_ = toLabImage(look->front());
        result_.delivered.format = format_.name;
        result_.delivered.goalDeltaE = format_.goalDeltaE;
        result_.delivered.target = std::move(look->front());
        result_.delivered.targetToMatevo = meanDeltaE00(deliveredTargetLab_, belcourTargetLab_);
        result_.set.target = std::move(belcourTarget);
        return Ok{};
    }

    // Offers `variant` (its Belcour render at the output size): true when it joined the set.
    Result<bool> offer(Variant variant) {
        offered_.push_back(variant.genome);
        LabImage belcourLab = toLabImage(variant.image);
        variant.deltaEToTarget = meanDeltaE00(belcourTargetLab_, belcourLab);
        std::vector<double> belcourDistances = distancesTo(belcourLab, belcourLabs_);
        if (!variant.kept && !holds(variant.deltaEToTarget, belcourDistances)) return false;
        // The first conversion that holds, unless it misses the conversion's own goal and a
        // later one holds within it. A kept variant is delivered whatever its looks, by the
        // first conversion that holds too, else by the first within the goal.
        std::optional<Look> chosen;
        int chosenRank = -1;
        for (int attempt = 0; attempt < std::max(format_.attempts, 1); ++attempt) {
            auto look = checkedImages(format_.render(std::span(&variant.genome, 1), attempt), 1,
                                      format_.name);
            if (!look) return look.error();
            ++result_.delivered.conversions;
            Look candidate{{std::move(look->front()), 0.0, 0.0, attempt}, {}, {}};
            candidate.lab = toLabImage(candidate.variant.image);
            candidate.variant.deltaEToTarget = meanDeltaE00(deliveredTargetLab_, candidate.lab);
            candidate.variant.deltaEToMatevo = meanDeltaE00(candidate.lab, belcourLab);
            candidate.distances = distancesTo(candidate.lab, deliveredLabs_);
            const bool holdsHere = holds(candidate.variant.deltaEToTarget, candidate.distances);
            if (!variant.kept && !holdsHere) continue;
            const int rank = (holdsHere ? 2 : 0) +
                             (candidate.variant.deltaEToMatevo <= format_.goalDeltaE ? 1 : 0);
            if (rank > chosenRank) {
                chosen = std::move(candidate);
                chosenRank = rank;
            }
            if (chosenRank == 3) break;
        }
        if (!chosen) return false;
        if (chosen->variant.attempt > 0) ++result_.delivered.refitted;
        result_.delivered.variants.push_back(std::move(chosen->variant));
        appendToPairwise(result_.delivered.pairwise, std::move(chosen->distances));
        deliveredLabs_.push_back(std::move(chosen->lab));
        appendToPairwise(result_.set.pairwise, std::move(belcourDistances));
        belcourLabs_.push_back(std::move(belcourLab));
        result_.set.variants.push_back(std::move(variant));
        return true;
    }

    bool wasOffered(const Genome& genome) const {
        return std::find(offered_.begin(), offered_.end(), genome) != offered_.end();
    }
    std::size_t accepted() const { return result_.set.variants.size(); }
    std::size_t& outputRenders() { return result_.set.outputRenders; }
    std::size_t& replaced() { return result_.delivered.replaced; }

    DeliveredVariants finish() && {
        result_.set.smallestPairwise = smallestPairwise(result_.set.pairwise);
        result_.delivered.smallestPairwise = smallestPairwise(result_.delivered.pairwise);
        return std::move(result_);
    }

private:
    // One conversion of a variant, measured.
    struct Look {
        DeliveredVariant variant;
        LabImage lab;
        std::vector<double> distances;  // to the delivered looks accepted before
    };

    bool holds(double toTarget, const std::vector<double>& distances) const {
        return request_.band.contains(toTarget) &&
               std::all_of(distances.begin(), distances.end(),
                           [&](double distance) { return distance >= request_.minApart; });
    }

    static std::vector<double> distancesTo(const LabImage& lab, const std::vector<LabImage>& labs) {
        std::vector<double> distances;
        for (const LabImage& other : labs) distances.push_back(meanDeltaE00(lab, other));
        return distances;
    }

    const VariantRequest& request_;
    const DeliveryFormat& format_;
    LabImage belcourTargetLab_, deliveredTargetLab_;
    std::vector<LabImage> belcourLabs_, deliveredLabs_;
    std::vector<Genome> offered_;
    DeliveredVariants result_;
};

// Converts `genomes` in one batch, so that a format can convert them side by side; the
// checker's single requests then find them made.
Status convertAhead(const DeliveryFormat& format, const std::vector<Genome>& genomes) {
    if (genomes.empty()) return Ok{};
    auto looks = checkedImages(format.render(genomes, 0), genomes.size(), format.name);
    if (!looks) return looks.error();
    return Ok{};
}

}  // namespace

Result<DeliveredVariants> checkDelivery(const VariantArchive& archive, VariantSet chosen,
                                        const VariantRequest& request, const Genome& target,
                                        const RenderGenomes& outputRender,
                                        const DeliveryFormat& format) {
    DeliveryChecker checker(request, format);
    std::vector<Genome> genomes{target};
    for (const Variant& variant : chosen.variants) genomes.push_back(variant.genome);
    if (auto converted = convertAhead(format, genomes); !converted) return converted.error();
    if (auto started = checker.start(std::move(chosen.target), target); !started)
        return started.error();
    checker.outputRenders() = chosen.outputRenders;
    for (Variant& variant : chosen.variants)
        if (auto offered = checker.offer(std::move(variant)); !offered) return offered.error();

    // Refill from the archive, as many candidates at a time as are still missing; each is
    // converted only when it holds on the Belcour render.
    const auto wanted = std::size_t(std::max(request.count, 0));
    const std::vector<std::size_t> order = spreadOrder(archive, request.band);
    std::size_t next = 0;
    while (checker.accepted() < wanted && next < order.size()) {
        std::vector<Genome> batch;
        for (; next < order.size() && batch.size() < wanted - checker.accepted(); ++next) {
            const Genome& genome = archive.members()[order[next]].genome;
            if (!checker.wasOffered(genome)) batch.push_back(genome);
        }
        auto images = checkedImages(outputRender(batch), batch.size(), "the renderer");
        if (!images) return images.error();
        checker.outputRenders() += batch.size();
        for (std::size_t k = 0; k < batch.size() && checker.accepted() < wanted; ++k) {
            auto offered = checker.offer({batch[k], std::move((*images)[k]), 0.0, false, {}});
            if (!offered) return offered.error();
            if (*offered) ++checker.replaced();
        }
    }
    return std::move(checker).finish();
}

Result<DeliveredSet> deliverSetAsItIs(VariantSet set, const VariantRequest& request,
                                      const Genome& target, const DeliveryFormat& format) {
    for (Variant& variant : set.variants) variant.kept = true;
    VariantRequest whole = request;
    whole.count = int(set.variants.size());
    // No archive: nothing is replaced, so nothing is rendered on matevo's side.
    const RenderGenomes renderNothing = [](std::span<const Genome>) -> Result<std::vector<Image>> {
        return internalError("the delivery of a set as it is renders no replacement");
    };
    auto delivered = checkDelivery(VariantArchive(request.minApart), std::move(set), whole, target,
                                   renderNothing, format);
    if (!delivered) return delivered.error();
    return std::move(delivered->delivered);
}

bool deliveredHolds(const DeliveredSet& delivered, std::size_t member,
                    const VariantRequest& request) {
    if (!request.band.contains(delivered.variants[member].deltaEToTarget)) return false;
    const std::vector<double>& distances = delivered.pairwise[member];
    for (std::size_t other = 0; other < distances.size(); ++other)
        if (other != member && distances[other] < request.minApart) return false;
    return true;
}

}  // namespace matevo
