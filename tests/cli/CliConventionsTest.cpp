// The command-line conventions, end to end on the real executable: one message format
// ("matevo COMMAND: TEXT", one line), the documented exit statuses, "did you mean" for
// mistyped commands, options and preset names, options that would do nothing refused, presets
// by name, `matevo presets`, --version and `compare --fail-above`.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "image/ImageFile.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"
#include "support/TestImages.h"

namespace matevo {
namespace {

using testing::CommandOutput;
using testing::runCommand;
using testing::runMatevo;
using testing::shellQuoted;

// Exit 2, nothing on stdout, exactly one line on stderr that is `expectedLine`.
void expectUsageLine(const CommandOutput& run, const std::string& expectedLine) {
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_EQ(run.err, expectedLine + "\n");
    EXPECT_TRUE(run.out.empty()) << run.out;
}

TEST(CliConventions, MistypedCommandIsNotReadAsAPreset) {
    expectUsageLine(runMatevo("evolv --population 10"),
                    "matevo: unknown command 'evolv' (did you mean 'evolve'?); see matevo --help");
    expectUsageLine(runMatevo("comapre a.png b.png"),
                    "matevo: unknown command 'comapre' (did you mean 'compare'?); see matevo "
                    "--help");
    expectUsageLine(runMatevo("frobnicate"),
                    "matevo: unknown command 'frobnicate'; see matevo --help");
}

TEST(CliConventions, MistypedOptionGetsTheClosestOptionOfItsCommand) {
    expectUsageLine(runMatevo("evolve --populaton 10"),
                    "matevo evolve: unknown option '--populaton' (did you mean '--population'?); "
                    "see matevo evolve --help");
    expectUsageLine(runMatevo("compare --jsn a.png b.png"),
                    "matevo compare: unknown option '--jsn' (did you mean '--json'?); see matevo "
                    "compare --help");
    expectUsageLine(runMatevo("render --zzzzzz=3 --out x.png"),
                    "matevo render: unknown option '--zzzzzz'; see matevo render --help");
}

TEST(CliConventions, OptionsThatWouldDoNothingAreRefused) {
    expectUsageLine(runMatevo("evolve --size 32"),
                    "matevo evolve: --size does nothing without --out");
    expectUsageLine(runMatevo("evolve --backend cpu"),
                    "matevo evolve: --backend does nothing without --out");
    expectUsageLine(runMatevo("compare a.png b.png --range 0,5"),
                    "matevo compare: --range does nothing without --heatmap");
}

TEST(CliConventions, AnUnwritableOutputIsBadInputNotAnInternalFailure) {
    const auto run = runMatevo("render --backend cpu --size 8 --out /nonexistent-folder/x.png");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_EQ(run.err.rfind("matevo render: --out: /nonexistent-folder/x.png", 0), 0u) << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
}

// What an output needs besides its folder is looked for before the work starts: without the
// font of contact sheets and charts, `variants --out` and `experiment` stop at once with one
// line saying where the font was looked for (before even the estimate of a long run), rather
// than fail when they write, after the work. `timeout` only bounds the test should the work
// start: a million evaluations or a thousand runs take hours.
TEST(CliConventions, AMissingChartFontIsRefusedBeforeTheWork) {
    testing::ScratchFolder scratch("matevo_no_font");
    const std::string noFont = "XDG_DATA_HOME=" + shellQuoted(scratch / "home") +
                               " XDG_DATA_DIRS=" + shellQuoted(scratch / "share") +
                               " timeout 120 '" + MATEVO_BINARY_DIR + "/matevo' ";
    const std::string looked =
        ": cannot find the DejaVu Sans font (Debian: fonts-dejavu-core); looked in " +
        (scratch / "home" / "fonts/truetype/dejavu/DejaVuSans.ttf").string() + ", " +
        (scratch / "share" / "fonts/truetype/dejavu/DejaVuSans.ttf").string();
    const auto variants =
        runCommand(noFont + "variants --count 2 --band 2,10 --max-evaluations 1000000 --out " +
                   shellQuoted(scratch / "set"));
    expectUsageLine(variants, "matevo variants" + looked);
    EXPECT_FALSE(std::filesystem::exists(scratch / "set"));
    const auto experiment = runCommand(noFont + "experiment --runs 1000 --backend cpu --out " +
                                       shellQuoted(scratch / "runs"));
    expectUsageLine(experiment, "matevo experiment" + looked);
    EXPECT_FALSE(std::filesystem::exists(scratch / "runs"));
    // Without --out nothing is drawn, so nothing needs the font.
    const auto noOut = runCommand(noFont +
                                  "variants --count 1 --band 2,10 --size 16 "
                                  "--fitness-size 8 --max-evaluations 40 --backend cpu");
    EXPECT_TRUE(noOut.exitCode == 0 || noOut.exitCode == 3) << noOut.err;
    EXPECT_EQ(noOut.err.find("DejaVu"), std::string::npos) << noOut.err;
}

// The executable alone (an install that lost matevo's OpenImageIO module, which it looks for
// beside itself): an OpenEXR output is refused before the work, saying where the module was
// looked for, rather than after the run when it writes; PNG needs no module.
TEST(CliConventions, AnExrOutputWithoutTheImageModuleIsRefusedBeforeTheWork) {
    testing::ScratchFolder scratch("matevo_no_module");
    std::filesystem::create_directories(scratch / "bin");
    std::filesystem::copy_file(std::string(MATEVO_BINARY_DIR) + "/matevo", scratch / "bin/matevo");
    const std::string alone = "timeout 120 " + shellQuoted(scratch / "bin/matevo") + " ";
    const std::string preset = " --preset " + shellQuoted(std::string(MATEVO_SOURCE_DIR) +
                                                          "/presets/validation_metal.json");
    const std::string missing = ": matevo's OpenImageIO module is not installed (looked in " +
                                (scratch / "bin/lib/matevo/matevo_image_library.so").string();
    const auto evolve = runCommand(alone + "evolve" + preset +
                                   " --population 2000 --generations 100000 "
                                   "--format exr --out " +
                                   shellQuoted(scratch / "run"));
    EXPECT_EQ(evolve.exitCode, 2) << evolve.err;
    EXPECT_EQ(evolve.err.rfind("matevo evolve: --format exr" + missing, 0), 0u) << evolve.err;
    EXPECT_EQ(evolve.err.find('\n'), evolve.err.size() - 1) << evolve.err;
    EXPECT_FALSE(std::filesystem::exists(scratch / "run"));
    const auto render = runCommand(alone + "render" + preset + " --backend cpu --size 8 --out " +
                                   shellQuoted(scratch / "x.exr"));
    EXPECT_EQ(render.exitCode, 2) << render.err;
    EXPECT_EQ(render.err.rfind("matevo render: --out" + missing, 0), 0u) << render.err;
    const auto png = runCommand(alone + "render" + preset + " --backend cpu --size 8 --out " +
                                shellQuoted(scratch / "x.png"));
    EXPECT_EQ(png.exitCode, 0) << png.err;
}

// A log (stderr not a terminal) gets each notice as one "matevo COMMAND: " line and no progress
// redrawn with \r, as when the FGD/TIR tables are built for the first time; --quiet, nothing.
TEST(CliConventions, ALogGetsOneLinePerNoticeAndNoProgress) {
    testing::ScratchFolder scratch("matevo_log_lines");
    const std::string render = " '" MATEVO_BINARY_DIR "/matevo' render --size 16 --backend cpu";
    const auto logged = runCommand("XDG_CACHE_HOME=" + shellQuoted(scratch / "cache") + render +
                                   " --out " + shellQuoted(scratch / "a.png"));
    ASSERT_EQ(logged.exitCode, 0) << logged.err;
    EXPECT_EQ(logged.err.find('\r'), std::string::npos) << logged.err;
    EXPECT_EQ(std::count(logged.err.begin(), logged.err.end(), '\n'), 2) << logged.err;
    EXPECT_EQ(logged.err.rfind("matevo render: building the FGD/TIR tables", 0), 0u) << logged.err;
    EXPECT_NE(logged.err.find("\nmatevo render: tables built\n"), std::string::npos) << logged.err;
    const auto quiet = runCommand("XDG_CACHE_HOME=" + shellQuoted(scratch / "cache2") + render +
                                  " --quiet --out " + shellQuoted(scratch / "b.png"));
    ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
    EXPECT_EQ(quiet.err, "");
}

TEST(CliConventions, VersionAndHelp) {
    const auto version = runMatevo("--version");
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_EQ(version.out, std::string("matevo ") + MATEVO_VERSION + "\n");
    const auto help = runMatevo("--help");
    EXPECT_EQ(help.exitCode, 0);
    for (const char* command : {"edit", "evolve", "render", "compare", "experiment", "presets"})
        EXPECT_NE(help.out.find(std::string("  ") + command + " "), std::string::npos) << command;
    EXPECT_NE(help.out.find("3 compare --fail-above"), std::string::npos);
    const auto commandHelp = runMatevo("help evolve");
    EXPECT_EQ(commandHelp.exitCode, 0);
    EXPECT_EQ(commandHelp.out, runMatevo("evolve --help").out);
}

class PresetsByName : public ::testing::Test {
protected:
    // A user preset folder of our own, so the user's real presets never leak into the test.
    std::string withUserFolder(const std::string& arguments) {
        return "XDG_DATA_HOME=" + shellQuoted(scratch_.path()) + " '" + MATEVO_BINARY_DIR +
               "/matevo' " + arguments;
    }
    testing::ScratchFolder scratch_{"matevo_presets"};
};

TEST_F(PresetsByName, ListsShippedAndUserPresetsAndLoadsThemByName) {
    const auto userFolder = scratch_ / "matevo" / "presets";
    std::filesystem::create_directories(userFolder);
    std::filesystem::copy_file(
        std::filesystem::path(MATEVO_SOURCE_DIR) / "presets" / "validation_metal.json",
        userFolder / "my_metal.json");

    const auto list = runCommand(withUserFolder("presets"));
    ASSERT_EQ(list.exitCode, 0) << list.err;
    for (const char* name :
         {"validation_metal ", "validation_painted_metal ", "validation_metal_depth ", "my_metal "})
        EXPECT_NE(list.out.find(name), std::string::npos) << name << "\n" << list.out;
    EXPECT_NE(list.out.find("(yours)"), std::string::npos) << list.out;

    const auto byName =
        runCommand(withUserFolder("evolve --preset my_metal --json "
                                  "--population 4 --generations 0"));
    EXPECT_EQ(byName.exitCode, 0) << byName.err;
    const auto shipped =
        runCommand(withUserFolder("evolve --preset validation_metal_depth "
                                  "--population 4 --generations 0"));
    EXPECT_EQ(shipped.exitCode, 0) << shipped.err;
}

TEST_F(PresetsByName, AnUnknownNameSaysWhereItLookedAndSuggests) {
    const auto run =
        runCommand(withUserFolder("evolve --preset validation_metal_depht --generations 0"));
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_EQ(run.err.rfind("matevo evolve: no preset named 'validation_metal_depht' in " +
                                (scratch_ / "matevo" / "presets").string(),
                            0),
              0u)
        << run.err;
    EXPECT_NE(run.err.find("(did you mean 'validation_metal_depth'?)"), std::string::npos)
        << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
}

class FailAbove : public ::testing::Test {
protected:
    std::string write(const Image& image, const std::string& name) {
        EXPECT_TRUE(writeImage(image, scratch_ / name).ok());
        return shellQuoted(scratch_ / name);
    }
    testing::ScratchFolder scratch_{"matevo_fail_above"};
};

TEST_F(FailAbove, ExitsThreeOnlyWhenTheMeanIsAboveTheThreshold) {
    const std::string a = write(testdata::randomImage(16, 16, 1, false), "a.png");
    const std::string b = write(testdata::randomImage(16, 16, 2, false), "b.png");
    const auto same = runMatevo("compare " + a + " " + a + " --fail-above 0");
    EXPECT_EQ(same.exitCode, 0) << same.err;
    const auto different = runMatevo("compare " + a + " " + b + " --json --fail-above 1");
    EXPECT_EQ(different.exitCode, 3) << different.err;
    EXPECT_FALSE(different.out.empty());  // the figures are printed either way
    EXPECT_EQ(different.err.rfind("matevo compare: mean dE00 ", 0), 0u) << different.err;
    const auto lenient = runMatevo("compare " + a + " " + b + " --fail-above 1000");
    EXPECT_EQ(lenient.exitCode, 0) << lenient.err;
    expectUsageLine(runMatevo("compare " + a + " " + b + " --fail-above much"),
                    "matevo compare: --fail-above: expected a finite number, got 'much'");
}

}  // namespace
}  // namespace matevo
