// Every command of `matevo --help` on its ways to fail: an unknown option, a bad value, an input
// that is not there, an output that cannot be written and, where the command renders, no usable
// Vulkan (no driver, and the command told not to fall back). Each says exactly one line on
// stderr, "matevo COMMAND: TEXT" naming what is at fault, and exits with the documented status
// of its kind (app/Messages.h): 2 for what the user named, 1 for the machine.
// Sizes are tiny; the rows that would render fail before any work.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>

#include "support/RunCommand.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;

struct FailurePath {
    const char* command;    // as `matevo --help` lists it
    const char* what;       // the failure, also the test's name
    std::string arguments;  // after the command; {dir}, {file}, {image} are replaced
    int status;
    const char* mentions;    // the stderr line names this
    bool noVulkan = false;   // run without a Vulkan driver
    bool noDisplay = false;  // run without a display
};

// {dir}: an empty scratch folder; {file}: a regular file there (a folder "inside" it cannot be
// made, whoever runs the test, root included); {image}: a small shipped PNG.
const FailurePath kFailurePaths[] = {
    {"edit", "unknown_option", "--bogus", 2, "'--bogus'"},
    {"edit", "bad_value", "--frames 0", 2, "--frames"},
    {"edit", "missing_input", "/nonexistent/matevo/p.json", 2, "p.json"},
    {"edit", "no_display", "", 2, "no display", false, true},

    {"evolve", "unknown_option", "--bogus", 2, "'--bogus'"},
    {"evolve", "bad_value", "--population x", 2, "--population"},
    {"evolve", "missing_input", "--preset /nonexistent/matevo/p.json", 2, "p.json"},
    {"evolve", "unwritable_output", "--population 4 --generations 0 --out {file}/run", 2, "--out"},
    {"evolve", "no_vulkan",
     "--population 4 --generations 0 --size 8 --out {dir}/run --backend gpu --no-fallback", 1,
     "Vulkan", true},

    {"render", "unknown_option", "--bogus --out {dir}/x.png", 2, "'--bogus'"},
    {"render", "bad_value", "--size 0 --out {dir}/x.png", 2, "--size"},
    {"render", "missing_input", "--genome /nonexistent/matevo/g.json --out {dir}/x.png", 2,
     "g.json"},
    {"render", "unwritable_output", "--backend cpu --size 8 --out {file}/x.png", 2, "--out"},
    {"render", "no_vulkan", "--backend gpu --no-fallback --size 8 --out {dir}/x.png", 1, "Vulkan",
     true},

    {"compare", "unknown_option", "{image} {image} --bogus", 2, "'--bogus'"},
    {"compare", "bad_value", "{image} {image} --metric ssim", 2, "--metric"},
    {"compare", "missing_input", "/nonexistent/matevo/a.png {image}", 2, "a.png"},
    {"compare", "unwritable_output", "{image} {image} --heatmap {file}/h.png", 2, "--heatmap"},

    {"experiment", "unknown_option", "--bogus", 2, "'--bogus'"},
    {"experiment", "bad_value", "--runs 0", 2, "--runs"},
    {"experiment", "missing_input", "--preset /nonexistent/matevo/p.json", 2, "p.json"},
    {"experiment", "unwritable_output", "--runs 1 --population 4 --generations 0 --out {file}/e", 2,
     "--out"},
    {"experiment", "no_vulkan",
     "--runs 1 --population 4 --generations 0 --size 8 --out {dir}/e --backend gpu "
     "--no-fallback",
     1, "Vulkan", true},

    {"variants", "unknown_option", "--count 2 --band 1,2 --bogus", 2, "'--bogus'"},
    {"variants", "bad_value", "--count x --band 1,2", 2, "--count"},
    {"variants", "missing_input", "--preset /nonexistent/matevo/p.json --count 2 --band 1,2", 2,
     "p.json"},
    {"variants", "unwritable_output", "--count 2 --band 1,2 --size 8 --out {file}/v", 2, "--out"},
    {"variants", "no_vulkan",
     "--count 2 --band 1,2 --size 8 --fitness-size 8 --backend gpu --no-fallback", 1, "Vulkan",
     true},

    {"merge", "unknown_option", "--bogus", 2, "'--bogus'"},
    {"merge", "bad_value", "{dir} --out", 2, "--out needs a value"},
    {"merge", "missing_input", "/nonexistent/matevo/share --out {dir}/m", 2, "share"},
    {"merge", "unwritable_output", "{dir} --out {file}/m", 2, "--out"},

    {"presets", "unknown_option", "--bogus", 2, "'--bogus'"},
    {"presets", "bad_value", "extra", 2, "'extra'"},

    {"bench", "unknown_option", "--bogus", 2, "'--bogus'"},
    {"bench", "bad_value", "--only everything", 2, "--only"},

    {"export", "unknown_option", "--bogus --out {dir}/x.gltf", 2, "'--bogus'"},
    {"export", "bad_value", "--format obj --out {dir}/x.obj", 2, "--format"},
    {"export", "missing_input", "--genome /nonexistent/matevo/g.json --out {dir}/x.gltf", 2,
     "g.json"},
    {"export", "unwritable_output", "--backend cpu --fit-size 16 --out {file}/x.gltf", 2, "--out"},
    {"export", "no_vulkan", "--backend gpu --no-fallback --fit-size 16 --out {dir}/x.gltf", 1,
     "Vulkan", true},

    {"scene", "unknown_option", "--bogus --out {dir}/x.png", 2, "'--bogus'"},
    {"scene", "bad_value", "--size 0x0 --out {dir}/x.png", 2, "--size"},
    {"scene", "missing_input", "--mesh /nonexistent/matevo/m.obj --out {dir}/x.png", 2, "m.obj"},
    {"scene", "unwritable_output", "--size 16x16 --out {file}/x.png", 2, "--out"},
    {"scene", "no_vulkan", "--size 16x16 --out {dir}/x.png", 1, "Vulkan", true},
};

void PrintTo(const FailurePath& path, std::ostream* out) {
    *out << "matevo " << path.command << " " << path.arguments;
}

std::string replaced(std::string text, const std::string& placeholder, const std::string& by) {
    for (auto at = text.find(placeholder); at != std::string::npos;
         at = text.find(placeholder, at + by.size()))
        text.replace(at, placeholder.size(), by);
    return text;
}

class FailurePathsCli : public ::testing::TestWithParam<FailurePath> {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = info->name();
        std::replace(name.begin(), name.end(), '/', '_');
        scratch_ = fs::temp_directory_path() /
                   ("matevo_failure_" + name + "_" + std::to_string(::getpid()));
        fs::remove_all(scratch_);
        fs::create_directories(scratch_ / "dir");
        std::ofstream(scratch_ / "file") << "a file, not a folder\n";
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(scratch_, ignored);
    }

    fs::path scratch_;
};

TEST_P(FailurePathsCli, OneLineAndTheDocumentedStatus) {
    const FailurePath& path = GetParam();
    std::string arguments = replaced(path.arguments, "{dir}", (scratch_ / "dir").string());
    arguments = replaced(arguments, "{file}", (scratch_ / "file").string());
    arguments = replaced(arguments, "{image}",
                         std::string(MATEVO_SOURCE_DIR) + "/presets/textures/paint_roughness.png");
    std::string environment = "env";
    if (path.noVulkan)
        environment +=
            " VK_DRIVER_FILES=/nonexistent/matevo_icd.json "
            "VK_ICD_FILENAMES=/nonexistent/matevo_icd.json";
    if (path.noDisplay) environment += " -u DISPLAY -u WAYLAND_DISPLAY";
    const auto run = testing::runCommand(environment + " '" + MATEVO_BINARY_DIR + "/matevo' " +
                                         path.command + " " + arguments);
    EXPECT_EQ(run.exitCode, path.status) << run.err;
    const std::string prefix = std::string("matevo ") + path.command + ": ";
    EXPECT_EQ(run.err.rfind(prefix, 0), 0u) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_NE(run.err.find(path.mentions), std::string::npos) << path.mentions << "\n" << run.err;
}

INSTANTIATE_TEST_SUITE_P(EveryCommand, FailurePathsCli, ::testing::ValuesIn(kFailurePaths),
                         [](const ::testing::TestParamInfo<FailurePath>& row) {
                             return std::string(row.param.command) + "_" + row.param.what;
                         });

// Every command `matevo --help` lists has rows above.
TEST(FailurePathsCli, EveryCommandOfTheHelpHasItsRows) {
    const auto help = testing::runMatevo("--help");
    ASSERT_EQ(help.exitCode, 0);
    const auto start = help.out.find("commands:");
    ASSERT_NE(start, std::string::npos) << help.out;
    const auto commands = help.out.substr(start, help.out.find("\n\n", start) - start);
    std::size_t listed = 0;
    for (std::size_t at = commands.find("\n  "); at != std::string::npos;
         at = commands.find("\n  ", at + 1)) {
        const std::string name = commands.substr(at + 3, commands.find(' ', at + 3) - at - 3);
        ++listed;
        const bool covered =
            std::any_of(std::begin(kFailurePaths), std::end(kFailurePaths),
                        [&](const FailurePath& path) { return name == path.command; });
        EXPECT_TRUE(covered) << name;
    }
    EXPECT_EQ(listed, 11u) << commands;
}

}  // namespace
}  // namespace matevo
