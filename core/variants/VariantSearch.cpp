#include "variants/VariantSearch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "evolve/Mutation.h"
#include "evolve/OperatorRates.h"
#include "evolve/Random.h"

namespace matevo {
namespace {

constexpr int kGenerationsPerPopulationOfEvaluations = 4;
// Mutations tried on an offspring that was rendered before; each redraws about one chromosome.
constexpr int kRenewAttempts = 32;

bool listed(const std::vector<Genome>& genomes, const Genome& genome) {
    return std::find(genomes.begin(), genomes.end(), genome) != genomes.end();
}

// Variants of the target by the paper's mutation operator (each active chromosome redrawn
// inside what Table 2 allows with the paper's per-chromosome rate), redrawn until at least one
// chromosome changed, so none is the target itself.
Genome mutantOf(const Genome& target, const FamilyRules& rules, Random& random) {
    const OperatorRates rates;
    Genome mutant = target;
    while (mutant == target) mutateChromosomes(mutant, rules, rates.chromosomeMutation, random);
    return mutant;
}

// A genome as the GA starts from it: with the kappa genes active and not yet carried (the
// target, a variant kept from a set without hue variety), they take the preset's kappa, brought
// into their bounds, so that it renders as before.
Genome withKappaGenes(Genome genome, const std::array<double, 3>& presetKappa,
                      const FamilyRules& rules) {
    if (genome.carriesKappa()) return genome;
    for (std::size_t i = kKappaR; i <= kKappaB; ++i)
        if (rules.ranges[i].active)
            genome[i] =
                std::clamp(presetKappa[i - kKappaR], rules.ranges[i].min, rules.ranges[i].max);
    return genome;
}

}  // namespace

VariantSearch::VariantSearch(const VariantRequest& request, const VariantSearchSettings& settings,
                             LightingRenderCache cache)
    : request_(request),
      settings_(settings),
      searchBand_(request.band.inset(settings.bandMargin)),
      cache_(std::move(cache)),
      archive_(request.minApart + settings.apartMargin) {
    progress_.closestDeltaE = std::numeric_limits<double>::quiet_NaN();
}

Result<std::unique_ptr<VariantSearch>> VariantSearch::start(const MaterialInstance& target,
                                                            const VariantRequest& request,
                                                            const VariantSearchSettings& settings,
                                                            const LightingRenders& render) {
    if (render.count() != std::max<std::size_t>(1, request.lightings.size()))
        return internalError("the variant search was given " + std::to_string(render.count()) +
                             " renderings for " + std::to_string(request.lightings.size()) +
                             " lightings");
    auto cache = LightingRenderCache::create(render, target.genome);
    if (!cache) return cache.error();
    std::unique_ptr<VariantSearch> search(
        new VariantSearch(request, settings, std::move(cache).value()));

    if (auto rendered = search->cache_.renderMissing(request.keep); !rendered)
        return rendered.error();
    for (const Genome& kept : request.keep)
        search->archive_.pin(kept, search->cache_.labs(kept), search->cache_.deltaEsToTarget(kept));

    // Two streams from the one seed: the initial variants and the GA's operators.
    SplitMix64 seeds(request.seed);
    Random initialRandom(seeds.next());
    GaSettings ga;
    ga.seed = seeds.next();
    ga.population = std::max(settings.population, 2);
    // A bound for a population that has converged to copies of what it has already rendered.
    ga.generations = std::max(1, kGenerationsPerPopulationOfEvaluations *
                                     std::max(settings.maxEvaluations, 0) / ga.population);
    ga.elitism = 0;
    ga.kappaGenes = request.kappaGenes;
    const Genome origin =
        withKappaGenes(target.genome, target.baseKappa, familyRules(target.family, ga.kappaGenes));
    search->ga_.emplace(
        target.family, origin, ga,
        [self = search.get()](std::span<const Genome> genomes, std::span<double> fitness) {
            self->score(genomes, fitness);
        });
    const FamilyRules& rules = search->ga_->rules();
    std::vector<Genome> initial;
    for (const Genome& kept : request.keep)
        if (initial.size() < std::size_t(ga.population))
            initial.push_back(withKappaGenes(kept, target.baseKappa, rules));
    while (initial.size() < std::size_t(ga.population))
        initial.push_back(mutantOf(origin, rules, initialRandom));
    search->ga_->setOffspringHook(
        [self = search.get()](std::span<Genome> offspring, Random& random) {
            self->renewSeen(offspring, random);
        });
    search->ga_->initialize(std::move(initial));
    if (search->renderFailure_) return *search->renderFailure_;
    return search;
}

void VariantSearch::score(std::span<const Genome> genomes, std::span<double> fitness) {
    if (!renderFailure_)
        if (auto rendered = cache_.renderMissing(genomes); !rendered)
            renderFailure_ = rendered.error();
    if (renderFailure_) {
        std::fill(fitness.begin(), fitness.end(), std::numeric_limits<double>::infinity());
        return;
    }
    for (const Genome& genome : genomes) {
        seen_.insert(genome);
        std::vector<double> deltaEs = cache_.deltaEsToTarget(genome);
        const double deltaE = worstDeltaE(request_.band, deltaEs);
        if (std::isnan(progress_.closestDeltaE) ||
            request_.band.violation(deltaE) < request_.band.violation(progress_.closestDeltaE))
            progress_.closestDeltaE = deltaE;
        if (!inBandUnderEvery(searchBand_, deltaEs) || listed(request_.exclude, genome) ||
            novelty_.contains(genome))
            continue;
        // Measured once against the whole archive: for the offer and as the novelty.
        LabsPerLighting labs = cache_.labs(genome);
        const std::vector<double> distances = archive_.distancesTo(labs);
        Novelty entry{std::numeric_limits<double>::infinity(), 0, archive_.lastId()};
        for (std::size_t i = 0; i < distances.size(); ++i)
            if (distances[i] < entry.nearest && !(archive_.members()[i].genome == genome)) {
                entry.nearest = distances[i];
                entry.nearestId = archive_.members()[i].id;
            }
        novelty_.emplace(genome, entry);
        archive_.offer(genome, std::move(labs), std::move(deltaEs), distances);
    }
    // Novelty is capped: beyond twice the spacing asked for, more distance buys nothing.
    const double cap = 2 * archive_.minApart();
    for (std::size_t i = 0; i < genomes.size(); ++i) {
        const double violation = bandViolation(searchBand_, cache_.deltaEsToTarget(genomes[i]));
        if (violation > 0)
            fitness[i] = violation;
        else
            fitness[i] = settings_.novelty ? -std::min(cap, novelty(genomes[i])) : 0.0;
    }
    progress_.evaluations = cache_.renderCount();
    progress_.archived = archive_.size();
}

double VariantSearch::novelty(const Genome& genome) {
    Novelty& entry = novelty_[genome];
    if (entry.nearestId != 0 && !archive_.holds(entry.nearestId))
        entry = {};  // the nearest member left: measure again from scratch
    if (entry.nearestId == 0 && entry.checkedUpTo == 0)
        entry.nearest = std::numeric_limits<double>::infinity();
    if (archive_.lastId() <= entry.checkedUpTo) return entry.nearest;
    const LabsPerLighting labs = cache_.labs(genome);
    for (const ArchivedVariant& member : archive_.members()) {
        if (member.id <= entry.checkedUpTo || member.genome == genome) continue;
        const double distance = apartUnderEvery(labs, member.labs);
        if (distance < entry.nearest) {
            entry.nearest = distance;
            entry.nearestId = member.id;
        }
    }
    entry.checkedUpTo = archive_.lastId();
    return entry.nearest;
}

void VariantSearch::renewSeen(std::span<Genome> offspring, Random& random) const {
    const OperatorRates rates;
    std::unordered_set<Genome, GenomeHash> thisGeneration;
    for (Genome& child : offspring) {
        for (int attempt = 0;
             attempt < kRenewAttempts && (seen_.contains(child) || thisGeneration.contains(child));
             ++attempt)
            mutateChromosomes(child, ga_->rules(), rates.chromosomeMutation, random);
        thisGeneration.insert(child);
    }
}

Status VariantSearch::step() {
    if (renderFailure_) return *renderFailure_;
    ga_->step();
    if (settings_.novelty) ga_->rescore();  // the archive moved on since they were scored
    std::vector<Genome> current;
    for (const Individual& individual : ga_->population()) current.push_back(individual.genome);
    cache_.forgetAllBut(current);
    std::erase_if(novelty_, [&](const auto& entry) { return !cache_.contains(entry.first); });
    progress_.generation = ga_->generation();
    if (renderFailure_) return *renderFailure_;
    return Ok{};
}

bool VariantSearch::finished() const {
    return renderFailure_ || ga_->finished() || archive_.size() >= wantedArchiveSize() ||
           cache_.renderCount() >= std::size_t(std::max(settings_.maxEvaluations, 0));
}

Status VariantSearch::run(const CancelToken& cancel, const VariantSearchObserver& onGeneration) {
    while (!finished() && !cancel.cancelled()) {
        if (auto stepped = step(); !stepped) return stepped;
        if (onGeneration) onGeneration(progress_);
    }
    return Ok{};
}

std::size_t VariantSearch::wantedArchiveSize() const {
    return std::size_t(std::max(request_.count, 0) + std::max(settings_.spare, 0));
}

}  // namespace matevo
