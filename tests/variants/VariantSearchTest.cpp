#include "variants/VariantSearch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include "../genome/TestGenomes.h"
#include "color/ImageDifference.h"
#include "fitness/ImageFitness.h"
#include "scene/SphereRenderer.h"
#include "variants/FindVariants.h"
#include "variants/VariantSet.h"

namespace matevo {
namespace {

constexpr std::array<double, 3> kPresetKappa = {3.1, 2.9, 2.8};

// Genomes of a family on the CPU reference renderer (the same scene as every back end), with
// the preset's kappa unless they carry their own (hue variety).
RenderGenomes cpuRenderer(int size, const MaterialFamily& family = kClearcoatConductor) {
    return [size, family](std::span<const Genome> genomes) -> Result<std::vector<Image>> {
        std::vector<Image> images;
        for (const Genome& genome : genomes)
            images.push_back(renderSphereCpu(materialOf(genome, family, kPresetKappa),
                                             SceneTextures{}, SceneSettings{}, size));
        return images;
    };
}

const MaterialInstance kValidationMetal{validationMetal(), kClearcoatConductor, kPresetKappa};

constexpr int kFitnessSize = 32;
constexpr int kOutputSize = 64;

VariantRequest smallRequest() {
    VariantRequest request;
    request.count = 6;
    request.band = {2, 5};
    request.minApart = 2;
    request.seed = 7;
    return request;
}

std::unique_ptr<VariantSearch> runSearch(const VariantRequest& request,
                                         const VariantSearchSettings& settings = {}) {
    auto search =
        VariantSearch::start(kValidationMetal, request, settings, cpuRenderer(kFitnessSize));
    EXPECT_TRUE(search.ok());
    if (!search) return nullptr;
    EXPECT_TRUE((*search)->run().ok());
    return std::move(search).value();
}

std::vector<Genome> archiveGenomes(const VariantSearch& search) {
    std::vector<Genome> genomes;
    for (const auto& member : search.archive().members()) genomes.push_back(member.genome);
    return genomes;
}

Image renderOne(const Genome& genome, int size) {
    return cpuRenderer(size)(std::span(&genome, 1))->front();
}

double meanDeltaE(const Image& a, const Image& b) {
    auto map = compareImages(a, b);
    EXPECT_TRUE(map.ok());
    return map ? map->stats.mean : -1;
}

// The archive's invariant at the fitness resolution, and the delivered set's at the output
// resolution, re-measured here with compareImages on the set's own images.
TEST(VariantSearch, DeliversTheRequestedSetInsideTheBandAndApart) {
    const VariantRequest request = smallRequest();
    auto search = runSearch(request);
    ASSERT_TRUE(search);
    for (const auto& member : search->archive().members())
        EXPECT_TRUE(request.band.contains(member.deltaEToTarget[0])) << member.deltaEToTarget[0];
    for (std::size_t i = 0; i < search->archive().size(); ++i)
        for (std::size_t j = i + 1; j < search->archive().size(); ++j)
            EXPECT_GE(search->archive().distance(i, j), request.minApart);

    auto set =
        chooseVariantSet(search->archive(), request, validationMetal(), cpuRenderer(kOutputSize));
    ASSERT_TRUE(set.ok());
    ASSERT_TRUE(fulfils(*set, request)) << set->variants.size() << " variants";
    const Image target = renderOne(validationMetal(), kOutputSize);
    for (std::size_t i = 0; i < set->variants.size(); ++i) {
        const double toTarget = meanDeltaE(target, set->variants[i].image);
        EXPECT_NEAR(toTarget, set->variants[i].deltaEToTarget, 1e-6);
        EXPECT_TRUE(request.band.contains(toTarget)) << "variant " << i << ": " << toTarget;
        for (std::size_t j = i + 1; j < set->variants.size(); ++j) {
            const double apart = meanDeltaE(set->variants[i].image, set->variants[j].image);
            EXPECT_NEAR(apart, set->pairwise[i][j], 1e-6);
            EXPECT_GE(apart, request.minApart) << i << ", " << j;
            EXPECT_FALSE(set->variants[i].genome == set->variants[j].genome);
        }
    }
    EXPECT_GT(set->smallestPairwise, request.minApart);
}

TEST(VariantSearch, SameSeedSameSetOtherSeedOtherSet) {
    VariantRequest request = smallRequest();
    auto first = runSearch(request);
    auto second = runSearch(request);
    ASSERT_TRUE(first && second);
    EXPECT_EQ(archiveGenomes(*first), archiveGenomes(*second));
    EXPECT_EQ(first->progress().evaluations, second->progress().evaluations);
    request.seed = 8;
    auto other = runSearch(request);
    ASSERT_TRUE(other);
    EXPECT_NE(archiveGenomes(*first), archiveGenomes(*other));
}

// The paper's operators and Table 2 hold for every individual the search makes.
TEST(VariantSearch, EveryIndividualSatisfiesTable2) {
    // More variants than the small request, so that the search runs several generations
    // whatever the renders' last digits (it once finished after 96 individuals).
    VariantRequest request = smallRequest();
    request.count = 12;
    auto search = VariantSearch::start({validationMetalDepth(), kMetalDepth, kPresetKappa}, request,
                                       {}, cpuRenderer(16, kMetalDepth));
    ASSERT_TRUE(search.ok());
    int checked = 0;
    do {
        for (const Individual& individual : (*search)->ga().population()) {
            ASSERT_TRUE(satisfiesTable2(individual.genome, kMetalDepth));
            ++checked;
        }
    } while (!(*search)->finished() && (*search)->step().ok());
    EXPECT_GT(checked, 100);
}

// Hue variety: the kappa genes go through the same operators, inside their bounds, for every
// individual, and the paper's 12 chromosomes still satisfy Table 2.
TEST(VariantSearch, HueVarietyKeepsEveryKappaGeneInsideItsBounds) {
    VariantRequest request = smallRequest();
    request.kappaGenes = KappaGenes::On;
    request.count = 40;  // more than the band holds at this spacing: the search runs long
    auto search = VariantSearch::start({validationMetalDepth(), kMetalDepth, kPresetKappa}, request,
                                       {}, cpuRenderer(16, kMetalDepth));
    ASSERT_TRUE(search.ok());
    const FamilyRules hueRules = familyRules(kMetalDepth, KappaGenes::On);
    std::set<std::array<double, 3>> kappas;
    int checked = 0;
    do {
        for (const Individual& individual : (*search)->ga().population()) {
            const Genome& genome = individual.genome;
            const auto problem = validateGenome(genome, hueRules);
            ASSERT_FALSE(problem) << *problem;
            for (std::size_t i = kKappaR; i <= kKappaB; ++i) {
                ASSERT_GE(genome[i], kKappaGeneMin);
                ASSERT_LE(genome[i], kKappaGeneMax);
            }
            ASSERT_TRUE(
                satisfiesTable2(materialOf(genome, kMetalDepth, kPresetKappa).genome, kMetalDepth));
            kappas.insert(genome.kappa());
            ++checked;
        }
    } while (!(*search)->finished() && (*search)->step().ok());
    EXPECT_GT(checked, 100);
    EXPECT_GT(kappas.size(), 10u) << "the operators vary kappa";
}

TEST(VariantSearch, HueVarietyIsOffByDefault) {
    EXPECT_EQ(VariantRequest{}.kappaGenes, KappaGenes::Off);
    auto search = runSearch(smallRequest());
    ASSERT_TRUE(search);
    EXPECT_FALSE(search->rules().ranges[kKappaR].active);
    for (const auto& member : search->archive().members())
        EXPECT_FALSE(member.genome.carriesKappa());
    for (const Individual& individual : search->ga().population())
        EXPECT_FALSE(individual.genome.carriesKappa());
}

TEST(VariantSearch, KeptVariantsStayAndDiscardedOnesNeverReturn) {
    const VariantRequest first = smallRequest();
    auto search = runSearch(first);
    ASSERT_TRUE(search);
    auto set =
        chooseVariantSet(search->archive(), first, validationMetal(), cpuRenderer(kOutputSize));
    ASSERT_TRUE(set.ok() && set->variants.size() >= 3);

    VariantRequest refill = first;
    refill.keep = {set->variants[0].genome, set->variants[1].genome};
    refill.exclude = {set->variants[2].genome};
    refill.seed = 99;
    auto again = runSearch(refill);
    ASSERT_TRUE(again);
    auto refilled =
        chooseVariantSet(again->archive(), refill, validationMetal(), cpuRenderer(kOutputSize));
    ASSERT_TRUE(refilled.ok());
    ASSERT_GE(refilled->variants.size(), 2u);
    EXPECT_EQ(refilled->variants[0].genome, refill.keep[0]);
    EXPECT_EQ(refilled->variants[1].genome, refill.keep[1]);
    EXPECT_TRUE(refilled->variants[0].kept && refilled->variants[1].kept);
    for (std::size_t i = 2; i < refilled->variants.size(); ++i) {
        EXPECT_FALSE(refilled->variants[i].kept);
        EXPECT_FALSE(refilled->variants[i].genome == refill.exclude[0]);
    }
}

TEST(VariantSearch, AnUnreachableBandEndsWithNothingAndSaysHowCloseItGot) {
    VariantRequest request = smallRequest();
    request.band = {60, 80};
    VariantSearchSettings settings;
    settings.maxEvaluations = 200;
    auto search = runSearch(request, settings);
    ASSERT_TRUE(search);
    EXPECT_TRUE(search->finished());
    EXPECT_EQ(search->archive().size(), 0u);
    EXPECT_GE(search->progress().evaluations, 200u);
    EXPECT_LT(search->progress().closestDeltaE, 60);
    EXPECT_GT(search->progress().closestDeltaE, 5);
    auto set =
        chooseVariantSet(search->archive(), request, validationMetal(), cpuRenderer(kOutputSize));
    ASSERT_TRUE(set.ok());
    EXPECT_TRUE(set->variants.empty());
    EXPECT_FALSE(fulfils(*set, request));
}

// The one function every caller runs: the search, then the set chosen at the output size; the
// caller follows each generation and may cancel early, and still gets the set found so far.
TEST(VariantSearch, FindVariantsIsTheSearchThenTheChoiceAndStopsWhenAsked) {
    const VariantRequest request = smallRequest();
    int generations = 0;
    auto countGenerations = [&](const VariantSearchProgress& progress) {
        EXPECT_EQ(progress.generation, ++generations);
    };
    auto found = findVariants(kValidationMetal, request, {}, cpuRenderer(kFitnessSize),
                              cpuRenderer(kOutputSize), {}, countGenerations);
    ASSERT_TRUE(found.ok()) << found.error().message;
    EXPECT_EQ(found->progress.generation, generations);
    EXPECT_GT(generations, 0);
    auto search = runSearch(request);
    ASSERT_TRUE(search);
    auto set =
        chooseVariantSet(search->archive(), request, validationMetal(), cpuRenderer(kOutputSize));
    ASSERT_TRUE(set.ok());
    ASSERT_EQ(found->set.variants.size(), set->variants.size());
    for (std::size_t i = 0; i < set->variants.size(); ++i)
        EXPECT_EQ(found->set.variants[i].genome, set->variants[i].genome);
    EXPECT_EQ(found->progress.evaluations, search->progress().evaluations);

    const CancelToken cancel;
    generations = 0;
    auto stopped =
        findVariants(kValidationMetal, request, {}, cpuRenderer(kFitnessSize),
                     cpuRenderer(kOutputSize), cancel, [&](const VariantSearchProgress& progress) {
                         countGenerations(progress);
                         cancel.cancel();  // seen before the next generation
                     });
    ASSERT_TRUE(stopped.ok());
    EXPECT_EQ(stopped->progress.generation, 1);
    EXPECT_LT(stopped->progress.evaluations, found->progress.evaluations);
    for (const Variant& variant : stopped->set.variants)
        EXPECT_TRUE(request.band.contains(variant.deltaEToTarget)) << variant.deltaEToTarget;
}

TEST(VariantSearch, ARenderFailureIsAnError) {
    int calls = 0;
    auto failing = [&](std::span<const Genome> genomes) -> Result<std::vector<Image>> {
        if (++calls > 1) return environmentError("device lost");
        return cpuRenderer(8)(genomes);
    };
    auto search =
        VariantSearch::start(kValidationMetal, smallRequest(), {}, RenderGenomes(failing));
    ASSERT_FALSE(search.ok());
    EXPECT_EQ(search.error().message, "device lost");
}

// The image-space fitness is the rendered mean ΔE00 (the rule of compare), or the band's
// violation; the GA under it approaches the target in image space.
TEST(ImageSpaceFitness, ScoresRenderedDeltaEAndTheGaApproachesTheTarget) {
    auto cache = GenomeRenderCache::create(cpuRenderer(kFitnessSize), validationMetal());
    ASSERT_TRUE(cache.ok());
    ImageSpaceFitness fitness(std::move(cache).value());
    GaSettings settings;
    settings.population = 20;
    settings.generations = 6;
    settings.seed = 3;
    GeneticAlgorithm ga(kClearcoatConductor, validationMetal(), settings, fitness.evaluator());
    ga.run();
    ASSERT_FALSE(fitness.failure());
    const auto& history = ga.history();
    EXPECT_LE(history.back().best, history.front().best);
    const Individual best = ga.rankedPopulation().front();
    const Image target = renderOne(validationMetal(), kFitnessSize);
    const Image bestImage = renderOne(best.genome, kFitnessSize);
    EXPECT_NEAR(best.fitness, meanDeltaE(target, bestImage), 1e-9);
    EXPECT_LE(fitness.renderCount(), std::size_t(20 * 7));

    auto bandCache = GenomeRenderCache::create(cpuRenderer(kFitnessSize), validationMetal());
    ASSERT_TRUE(bandCache.ok());
    ImageSpaceFitness banded(std::move(bandCache).value(), {2, 5});
    double score = -1;
    banded.evaluator()(std::span(&best.genome, 1), std::span(&score, 1));
    const DeltaEBand band{2, 5};
    EXPECT_DOUBLE_EQ(score, band.violation(best.fitness));
}

}  // namespace
}  // namespace matevo
