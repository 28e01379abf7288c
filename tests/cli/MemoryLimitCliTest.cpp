// --max-memory enforced while the work runs, not only estimated before it: under a limit, every
// command that renders or reads images either refuses the work up front (exit 2, its estimate
// is past the limit), or stops once its resident memory passes the limit (exit 1, one line,
// nothing written), or finishes with its peak resident memory (the kernel's account, as
// `/usr/bin/time -v` reports it) within the limit. Never exit 0 past the limit. The watch counts
// what is resident, so this holds under AddressSanitizer too, whose shadow memory is resident.
#include <sys/resource.h>
#include <sys/wait.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;
using testing::runMatevo;
using testing::shellQuoted;

const std::string kMatevo = std::string(MATEVO_BINARY_DIR) + "/matevo";

class MemoryLimitCli : public ::testing::Test {
protected:
    void SetUp() override { fs::create_directories(folder_ / "out"); }

    testing::ScratchFolder scratch_{"matevo_memory_limit"};
    const fs::path folder_ = scratch_.path();
};

struct LimitedRun {
    int exitCode = -1;
    std::string err;
    std::uint64_t peakBytes = 0;
};

// matevo ARGUMENTS --max-memory LIMIT, its stderr and its peak resident memory from wait4 (the
// shell execs matevo, so the account is matevo's).
LimitedRun runUnderLimit(const std::vector<std::string>& arguments, const std::string& limit,
                         const fs::path& errFile) {
    // Appended piece by piece: GCC 12 misreads " " + shellQuoted(...) (-Wrestrict).
    std::string line = "exec ";
    line += shellQuoted(kMatevo);
    for (const auto& argument : arguments) {
        line += ' ';
        line += shellQuoted(argument);
    }
    line += " --max-memory " + limit + " 2>";
    line += shellQuoted(errFile);
    const pid_t pid = testing::startProcess({"/bin/sh", "-c", line});
    int status = 0;
    struct rusage usage {};
    LimitedRun run;
    EXPECT_EQ(::wait4(pid, &status, 0, &usage), pid);
    if (WIFEXITED(status)) run.exitCode = WEXITSTATUS(status);
    run.peakBytes = std::uint64_t(usage.ru_maxrss) * 1024;  // kilobytes on Linux
    std::ifstream file(errFile);
    std::ostringstream text;
    text << file.rdbuf();
    run.err = text.str();
    return run;
}

std::uint64_t mebibytes(const std::string& limit) {
    return std::stoull(limit.substr(0, limit.size() - 1)) << 20;
}

// One of the three outcomes; `out` is written only by the third.
void expectRefusedStoppedOrWithin(const std::vector<std::string>& arguments,
                                  const std::string& limit, const fs::path& out,
                                  const fs::path& errFile) {
    const LimitedRun run = runUnderLimit(arguments, limit, errFile);
    const std::string request = arguments.front() + " under " + limit;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << request << ": " << run.err;
    switch (run.exitCode) {
        case 0:
            EXPECT_LE(run.peakBytes, mebibytes(limit)) << request << " exited 0 past the limit";
            EXPECT_TRUE(fs::exists(out)) << request;
            break;
        case 1:
            EXPECT_NE(run.err.find(": memory limit " + limit.substr(0, limit.size() - 1) +
                                   " MiB exceeded by "),
                      std::string::npos)
                << request << ": " << run.err;
            EXPECT_FALSE(fs::exists(out)) << request;
            break;
        case 2:
            EXPECT_NE(run.err.find(" needs about "), std::string::npos)
                << request << ": " << run.err;
            EXPECT_FALSE(fs::exists(out)) << request;
            break;
        default:
            ADD_FAILURE() << request << ": exit status " << run.exitCode << ": " << run.err;
    }
}

// Past the limit while its work runs, a command whose estimate fits stops: one line naming the
// limit, the work and the resident memory, exit status 1 (an error of the environment, not a
// signal's 130/143), and nothing written, not even a temporary file.
TEST_F(MemoryLimitCli, WorkPastTheLimitStopsWithOneLineAndExitStatus1) {
    // The search's own estimate at 16x16 is well under 40 MiB; the program with its Vulkan
    // driver is resident past it before the search is done.
    const LimitedRun run = runUnderLimit({"variants", "--band", "2,5", "--count", "2", "--size",
                                          "16", "--fitness-size", "16", "--backend", "gpu"},
                                         "40M", folder_ / "err.txt");
    EXPECT_EQ(run.exitCode, 1) << run.err;
    EXPECT_TRUE(std::regex_match(
        run.err, std::regex("matevo variants: memory limit 40 MiB exceeded by 2 variants at "
                            "16x16, [^\\n]*\\(resident [0-9.]+ MiB\\)\n")))
        << run.err;
    EXPECT_TRUE(fs::is_empty(folder_ / "out"));
}

// Requests whose estimates fit a limit their work may still pass, and ones the limit is just
// above or below.
TEST_F(MemoryLimitCli, UnderALimitWorkIsRefusedStoppedOrWithinIt) {
    const fs::path image = folder_ / "a.png";
    ASSERT_EQ(runMatevo("render --backend cpu --size 1024 --out " + shellQuoted(image)).exitCode,
              0);
    const fs::path out = folder_ / "out";
    const fs::path err = folder_ / "err.txt";
    expectRefusedStoppedOrWithin(
        {"render", "--backend", "cpu", "--size", "2048", "--out", (out / "r.png").string()}, "320M",
        out / "r.png", err);
    for (const std::string limit : {"160M", "320M"})
        expectRefusedStoppedOrWithin({"compare", image.string(), image.string(), "--heatmap",
                                      (out / "heatmap.png").string()},
                                     limit, out / "heatmap.png", err);
    for (const std::string limit : {"256M", "512M"})
        expectRefusedStoppedOrWithin({"scene", "--size", "1024x1024", "--instances", "500", "--out",
                                      (out / "scene.png").string()},
                                     limit, out / "scene.png", err);
    expectRefusedStoppedOrWithin({"export", "--fit-size", "16", "--fit-renders", "20",
                                  "--report-size", "1024", "--out", (out / "set.gltf").string()},
                                 "384M", out / "set.gltf", err);
}

}  // namespace
}  // namespace matevo
