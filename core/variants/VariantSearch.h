#pragma once
// The search for a set of variants (docs/variants.md): N materials whose renders lie inside a
// band of mean ΔE00 from the target and at least `minApart` from each other. A quality-diversity
// search: the paper's GA (§4.3 operators, Table 2 for every individual) evolves a population
// whose fitness is image-space — outside the band, how far outside; inside, how far the render
// lies from the nearest member of an archive of accepted variants (novelty) — and every
// in-band render is offered to that archive (VariantArchive). The population starts from
// variants of the target made by the paper's mutation, since variants are wanted near it.
// One generation per step(), so the editor can show progress. All rendering goes through a
// RenderGenomes at the fitness resolution, one per lighting the set must hold under
// (LightingMeasure.h): band and spacing then hold under every one; the search never touches a
// GPU API itself.
// Deterministic for a seed: the only parallel work (rendering, ΔE00) does not depend on the
// thread count.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "common/CancelToken.h"
#include "common/Result.h"
#include "evolve/GeneticAlgorithm.h"
#include "evolve/RenderGenomes.h"
#include "fitness/DeltaEBand.h"
#include "fitness/GenomeRenderCache.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"
#include "material/MaterialInstance.h"
#include "variants/LightingRenderCache.h"
#include "variants/VariantArchive.h"

namespace matevo {

// What the user asks for.
struct VariantRequest {
    int count = 12;
    DeltaEBand band{2.0, 5.0};
    double minApart = 2.0;  // mean ΔE00 between any two variants
    std::uint64_t seed = 1;
    // Variants the user keeps (refill the rest): they stay in the set as they are.
    std::vector<Genome> keep;
    // Variants the user discarded: never offered again.
    std::vector<Genome> exclude;
    // Hue variety, beyond the paper: the conductor base's kappa is evolved too (three more
    // genes, in FamilyRules' bounds, under the same operators), so variants may differ in
    // colour. Off, every variant has the preset's kappa.
    KappaGenes kappaGenes = KappaGenes::Off;
    // The lightings the set must hold under, by the names `--env` takes (paper, ambient, studio
    // or an environment file), in order; the search is given one render per lighting in this
    // order (LightingRenders). Empty: the preset's own scene alone, unnamed.
    std::vector<std::string> lightings;
};

// How the search runs; the defaults are chosen by measurement (docs/variants.md).
struct VariantSearchSettings {
    int population = 24;
    // Fitness-resolution renders before the search gives up.
    int maxEvaluations = 1500;
    // The archive accepts only renders this far inside the band and this much farther apart
    // than asked, so that the set still holds when measured again at the output resolution.
    double bandMargin = 0.05;
    double apartMargin = 0.05;
    // Archive members wanted beyond the count, so the final choice can spread the set and
    // replace a variant that fails at the output resolution.
    int spare = 4;
    // Novelty inside the band (the quality-diversity part). Off, every in-band render is
    // equally fit: the plain band-targeting GA that docs/variants.md compares against.
    bool novelty = true;
};

struct VariantSearchProgress {
    int generation = 0;
    std::size_t evaluations = 0;  // fitness-resolution renders so far
    std::size_t archived = 0;
    // The render nearest the band seen so far: its mean ΔE00 to the target.
    double closestDeltaE = 0;
};

// Told after every generation of run().
using VariantSearchObserver = std::function<void(const VariantSearchProgress&)>;

class VariantSearch {
public:
    // Renders the target and the kept variants, then the initial population, under every
    // lighting (one render each, max(1, request.lightings.size()) of them). The render
    // functions' images all have one size (the fitness resolution) and honour the kappa genes
    // (materialOf). With hue variety the population starts from the target's kappa, brought
    // into the genes' bounds.
    static Result<std::unique_ptr<VariantSearch>> start(const MaterialInstance& target,
                                                        const VariantRequest& request,
                                                        const VariantSearchSettings& settings,
                                                        const LightingRenders& render);

    // One generation; an Error when rendering failed.
    Status step();
    // Enough archive members, or the evaluations are spent.
    bool finished() const;
    // step() until finished() or `cancel` is cancelled (checked before every generation), which
    // ends the search with the archive it has; the one loop of every caller (FindVariants.h).
    Status run(const CancelToken& cancel = {}, const VariantSearchObserver& onGeneration = {});

    const VariantArchive& archive() const { return archive_; }
    const VariantSearchProgress& progress() const { return progress_; }
    const VariantRequest& request() const { return request_; }
    const FamilyRules& rules() const { return ga_->rules(); }
    // Every genome the GA has made so far (for the Table 2 tests).
    const GeneticAlgorithm& ga() const { return *ga_; }

private:
    // The nearest archive member seen from a genome's render, kept up to date incrementally:
    // only members that joined since (higher ids) are measured again, unless the nearest one
    // left the archive.
    struct Novelty {
        double nearest = 0;
        std::uint64_t nearestId = 0;    // 0: none
        std::uint64_t checkedUpTo = 0;  // every member with an id up to this one was measured
    };

    VariantSearch(const VariantRequest& request, const VariantSearchSettings& settings,
                  LightingRenderCache cache);
    void score(std::span<const Genome> genomes, std::span<double> fitness);
    double novelty(const Genome& genome);
    // Offspring already rendered (or twice in one generation) are mutated again until new, so
    // every generation spends its renders on new materials.
    void renewSeen(std::span<Genome> offspring, Random& random) const;
    std::size_t wantedArchiveSize() const;

    VariantRequest request_;
    VariantSearchSettings settings_;
    DeltaEBand searchBand_;
    LightingRenderCache cache_;
    VariantArchive archive_;
    std::optional<GeneticAlgorithm> ga_;
    std::unordered_map<Genome, Novelty, GenomeHash> novelty_;
    std::unordered_set<Genome, GenomeHash> seen_;
    VariantSearchProgress progress_;
    std::optional<Error> renderFailure_;
};

}  // namespace matevo
