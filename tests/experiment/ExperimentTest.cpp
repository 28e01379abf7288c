#include "experiment/Experiment.h"

#include <algorithm>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "color/ImageDifference.h"
#include "evolve/Random.h"
#include "experiment/ResultsCsv.h"
#include "experiment/RunSeeds.h"
#include "genome/FamilyRules.h"
#include "scene/SphereRenderer.h"

namespace matevo {
namespace {

ExperimentTarget validationMetal() {
    ExperimentTarget target;
    target.name = "validation metal";
    target.family = {Coat::Clearcoat, Base::Conductor, false, TexturedLayer::None};
    target.genome[kEta1] = 1.2;
    target.genome[kEta2] = 0.8;
    target.genome[kAlpha1] = 0.03;
    target.genome[kAlpha2] = 0.1;
    return target;
}

ExperimentSettings smallSettings(std::uint64_t seed) {
    ExperimentSettings settings;
    settings.runs = 6;
    settings.runsPerSeed = 3;
    settings.size = {12, 3};
    settings.seed = seed;
    return settings;
}

TEST(RunSeeds, ChangeEveryBlockAndDrawSuccessivelyFromTheBlockSeedWithin) {
    const std::uint64_t base = 42;
    EXPECT_EQ(blockSeed(base, 0, 9), base);
    EXPECT_EQ(blockSeed(base, 8, 9), base);
    EXPECT_EQ(blockSeed(base, 9, 9), base + 1);
    EXPECT_EQ(blockSeed(base, 35, 9), base + 3);

    for (int block = 0; block < 4; ++block) {
        SplitMix64 stream(base + std::uint64_t(block));
        for (int k = 0; k < 9; ++k) EXPECT_EQ(runSeed(base, block * 9 + k, 9), stream.next());
    }
    std::set<std::uint64_t> distinct;
    for (int run = 0; run < 36; ++run) distinct.insert(runSeed(base, run, 9));
    EXPECT_EQ(distinct.size(), 36u);
}

TEST(Experiment, EveryMetricRunsOnTheSameSeedsAndKeepsAValidBest) {
    const ExperimentTarget target = validationMetal();
    const ExperimentSettings settings = smallSettings(7);
    const auto records = evolveRuns(target, settings).value();
    ASSERT_EQ(records.size(), 3u * 6u);
    for (std::size_t i = 0; i < records.size(); ++i) {
        const RunRecord& record = records[i];
        EXPECT_EQ(record.metric, settings.metrics[i / 6]);
        EXPECT_EQ(record.run, int(i % 6));
        EXPECT_EQ(record.seed, runSeed(7, record.run, 3));
        EXPECT_EQ(record.size, settings.size);
        EXPECT_EQ(record.preset, target.name);
        EXPECT_GE(record.fitness, 0.0);
        EXPECT_EQ(validateGenome(record.genome, target.family), std::nullopt);
    }
}

TEST(Experiment, SameSeedGivesIdenticalResultsAndAnotherSeedDifferent) {
    const ExperimentTarget target = validationMetal();
    const std::string first = resultsCsv(evolveRuns(target, smallSettings(3)).value());
    EXPECT_EQ(first, resultsCsv(evolveRuns(target, smallSettings(3)).value()));
    EXPECT_NE(first, resultsCsv(evolveRuns(target, smallSettings(4)).value()));
}

// Cancelled after the first run ends, the runs not yet started are left out and those completed
// are returned as an uncancelled experiment has them; cancelled before, nothing runs.
TEST(Experiment, ACancelledExperimentReturnsTheRunsCompleted) {
    const ExperimentTarget target = validationMetal();
    const auto all = evolveRuns(target, smallSettings(3)).value();
    const CancelToken cancel;
    auto some = evolveRuns(
        target, smallSettings(3), [&](int, int) { cancel.cancel(); }, {}, cancel);
    ASSERT_TRUE(some.ok()) << some.error().message;
    EXPECT_GE(some->size(), 1u);
    EXPECT_LT(some->size(), all.size());
    for (const RunRecord& record : *some) {
        const auto same = std::find_if(all.begin(), all.end(), [&](const RunRecord& other) {
            return other.metric == record.metric && other.run == record.run;
        });
        ASSERT_NE(same, all.end());
        EXPECT_EQ(resultsCsvRow(record), resultsCsvRow(*same));
    }
    auto none = evolveRuns(target, smallSettings(3), {}, {}, cancel);
    ASSERT_TRUE(none.ok());
    EXPECT_TRUE(none->empty());
}

bool byDeltaE(const RunRecord& a, const RunRecord& b) { return a.meanDeltaE00 < b.meanDeltaE00; }

// The real CPU reference renderer at a small size, injected as the CLI injects it.
Image renderSmall(const ExperimentTarget& target, const Genome& genome) {
    return renderSphereCpu(MaterialInstance{genome, target.family, {3.1, 2.9, 2.8}}, {}, {}, 16);
}

TEST(Experiment, ScoresEachRunByTheMeanDeltaE00OfItsOwnRender) {
    const ExperimentTarget target = validationMetal();
    std::size_t batches = 0;
    const RenderGenomes render = [&](std::span<const Genome> genomes) {
        ++batches;
        std::vector<Image> images;
        for (const auto& genome : genomes) images.push_back(renderSmall(target, genome));
        return Result<std::vector<Image>>(std::move(images));
    };
    int lastDone = 0;
    auto records = runExperiment(target, smallSettings(5), render, [&](int done, int total) {
        EXPECT_GT(done, lastDone);
        EXPECT_EQ(total, 2 * 18);
        lastDone = done;
    });
    ASSERT_TRUE(records.ok()) << records.error().message;
    EXPECT_EQ(lastDone, 36);
    const Image targetImage = renderSmall(target, target.genome);
    for (const auto& record : *records) {
        auto expected = compareImages(targetImage, renderSmall(target, record.genome));
        ASSERT_TRUE(expected.ok());
        EXPECT_EQ(record.meanDeltaE00, expected->stats.mean);
    }
    EXPECT_EQ(batches, 2u);  // the target, then the 18 runs in one batch
    // Different best individuals look different: not every score is the same.
    EXPECT_NE(std::min_element(records->begin(), records->end(), byDeltaE)->meanDeltaE00,
              std::max_element(records->begin(), records->end(), byDeltaE)->meanDeltaE00);
}

// The image metric (beyond the paper) ranks by what is seen: on the same seeds as the paper's
// metrics, each run's fitness is its best render's mean ΔE00 at the fitness size, and its best
// materials land nearer the target than the genotype distance's.
TEST(Experiment, TheImageMetricRanksByRenderedDeltaE00AndChangesTheOutcome) {
    const ExperimentTarget target = validationMetal();
    ExperimentSettings settings = smallSettings(5);
    settings.metrics = {ExperimentMetric::Euclidean, ExperimentMetric::Image};
    settings.fitnessSize = 16;
    const RenderGenomes render = [&](std::span<const Genome> genomes) {
        std::vector<Image> images;
        for (const auto& genome : genomes) images.push_back(renderSmall(target, genome));
        return Result<std::vector<Image>>(std::move(images));
    };
    ASSERT_FALSE(evolveRuns(target, settings).ok()) << "the image metric needs a renderer";
    auto records = runExperiment(target, settings, render, {}, render);
    ASSERT_TRUE(records.ok()) << records.error().message;
    ASSERT_EQ(records->size(), 12u);
    std::vector<double> genotype, image;
    for (std::size_t i = 0; i < 6; ++i) {
        const RunRecord& paper = (*records)[i];
        const RunRecord& seen = (*records)[6 + i];
        EXPECT_EQ(paper.metric, ExperimentMetric::Euclidean);
        EXPECT_EQ(seen.metric, ExperimentMetric::Image);
        EXPECT_EQ(seen.seed, paper.seed) << "paired runs";
        EXPECT_EQ(validateGenome(seen.genome, target.family), std::nullopt);
        // Fitness and score are the same measure here (both renders are 16 px).
        EXPECT_NEAR(seen.fitness, seen.meanDeltaE00, 1e-9);
        genotype.push_back(paper.meanDeltaE00);
        image.push_back(seen.meanDeltaE00);
    }
    std::sort(genotype.begin(), genotype.end());
    std::sort(image.begin(), image.end());
    EXPECT_LT(image[3], genotype[3]) << "median mean ΔE00 of the runs' best";
    EXPECT_EQ(std::string(toString(ExperimentMetric::Image)), "image");
    EXPECT_EQ(parseExperimentMetric("image"), ExperimentMetric::Image);
    EXPECT_EQ(parseExperimentMetric("manhattan"), ExperimentMetric::Manhattan);
}

}  // namespace
}  // namespace matevo
