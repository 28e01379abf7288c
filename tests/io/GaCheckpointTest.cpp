// GA checkpoints read back exactly (every double, the generator's state) and refuse what does not
// belong to the run being resumed.
#include "documents/GaCheckpoint.h"

#include <fstream>

#include <gtest/gtest.h>

#include "support/ScratchFolder.h"

namespace matevo {
namespace {

GaCheckpoint checkpointAfter(int generations) {
    GaCheckpoint checkpoint;
    checkpoint.family.hasMedium = true;
    // A member of its family (Table 2), as a preset's target is.
    checkpoint.target[kEta1] = 1.3;
    checkpoint.target[kEta2] = 0.9;
    checkpoint.target[kAlpha1] = 0.05;
    checkpoint.target[kAlpha2] = 0.3;
    checkpoint.target[kDepth] = 1.0;
    checkpoint.target[kG] = 0.8;
    checkpoint.baseKappa = {3.1, 2.9, 2.8};
    checkpoint.settings.population = 12;
    checkpoint.settings.generations = 10;
    checkpoint.settings.seed = 0xfedcba9876543210ULL;  // the full 64-bit range
    checkpoint.settings.normalizeByRange = true;
    GeneticAlgorithm ga(checkpoint.family, checkpoint.target, checkpoint.settings);
    ga.initialize();
    while (ga.generation() < generations) ga.step();
    checkpoint.state = ga.state();
    return checkpoint;
}

TEST(GaCheckpoint, ReadsBackExactly) {
    testing::ScratchFolder folder("checkpoint");
    const GaCheckpoint written = checkpointAfter(4);
    ASSERT_TRUE(saveCheckpoint(written, folder / "run.json").ok());
    auto read = loadCheckpoint(folder / "run.json");
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(*read, written);  // bit-exact doubles and generator state
}

TEST(GaCheckpoint, MismatchesNameWhatDiffers) {
    const GaCheckpoint checkpoint = checkpointAfter(4);
    const auto mismatch = [&](auto change) {
        MaterialFamily family = checkpoint.family;
        Genome target = checkpoint.target;
        auto kappa = checkpoint.baseKappa;
        GaSettings settings = checkpoint.settings;
        change(family, target, kappa, settings);
        return checkpointMismatch(checkpoint, family, target, kappa, settings);
    };
    EXPECT_FALSE(mismatch([](auto&, auto&, auto&, auto&) {}));
    // Extending the run is allowed; going back before the checkpoint is not.
    EXPECT_FALSE(mismatch([](auto&, auto&, auto&, GaSettings& s) { s.generations = 50; }));
    EXPECT_NE(mismatch([](auto&, auto&, auto&, GaSettings& s) {
                  s.generations = 3;
              })->find("generation:"),
              std::string::npos);
    EXPECT_NE(mismatch([](auto&, auto&, auto&, GaSettings& s) { s.seed = 2; })->find("ga:"),
              std::string::npos);
    EXPECT_NE(mismatch([](auto&, Genome& t, auto&, auto&) { t[kEta1] = 1.4; })->find("target:"),
              std::string::npos);
    EXPECT_NE(mismatch([](MaterialFamily& f, auto&, auto&, auto&) {
                  f.hasMedium = false;
              })->find("family:"),
              std::string::npos);
}

TEST(GaCheckpoint, MalformedFilesNameTheField) {
    testing::ScratchFolder folder("checkpoint");
    std::string text = serializeCheckpoint(checkpointAfter(1));
    text.replace(text.find("\"random_state\""), 14, "\"random_statf\"");
    std::ofstream(folder / "bad.json") << text;
    auto read = loadCheckpoint(folder / "bad.json");
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().message.find("bad.json: random_state: missing"), std::string::npos)
        << read.error().message;
    std::ofstream(folder / "preset.json") << R"({"name": "not a checkpoint"})";
    auto preset = loadCheckpoint(folder / "preset.json");
    ASSERT_FALSE(preset.ok());
    EXPECT_NE(preset.error().message.find("format: missing"), std::string::npos);
}

TEST(GaCheckpoint, GenomesOutsideTable2AreRefused) {
    const GaCheckpoint valid = checkpointAfter(1);
    // eta1 of a dielectric coat is at most 2 in Table 2; the generous JSON bound is 1000.
    GaCheckpoint tamperedMember = valid;
    tamperedMember.state.population[3].genome[kEta1] = 7.5;
    auto member = parseCheckpoint(serializeCheckpoint(tamperedMember), "run.json");
    ASSERT_FALSE(member.ok());
    EXPECT_NE(member.error().message.find("run.json: population[3].genome: "), std::string::npos)
        << member.error().message;
    EXPECT_NE(member.error().message.find("Table 2"), std::string::npos) << member.error().message;

    GaCheckpoint tamperedTarget = valid;
    tamperedTarget.target[kG] = 0.2;  // Table 2 with this model: g in [0.7, 0.99]
    auto target = parseCheckpoint(serializeCheckpoint(tamperedTarget), "run.json");
    ASSERT_FALSE(target.ok());
    EXPECT_NE(target.error().message.find("run.json: target: "), std::string::npos)
        << target.error().message;
}

}  // namespace
}  // namespace matevo
