// The CPUs and memory a scheduler gives the process (common/CgroupLimits.h), read from cgroup v2
// files written by the test, and the thread count the real executable reports under taskset.
#include "common/CgroupLimits.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/MemoryBudget.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

TEST(CgroupLimits, CpuMaxIsQuotaOverPeriodOrNothing) {
    EXPECT_DOUBLE_EQ(*cpusAllowedByCpuMax("200000 100000\n"), 2.0);
    EXPECT_DOUBLE_EQ(*cpusAllowedByCpuMax("150000 100000"), 1.5);
    EXPECT_FALSE(cpusAllowedByCpuMax("max 100000\n"));
    EXPECT_FALSE(cpusAllowedByCpuMax(""));
    EXPECT_FALSE(cpusAllowedByCpuMax("lots 100000"));
    EXPECT_FALSE(cpusAllowedByCpuMax("100000 0"));
}

TEST(CgroupLimits, MemoryMaxIsBytesOrNothing) {
    EXPECT_EQ(*bytesAllowedByMemoryMax("2147483648\n"), 2147483648u);
    EXPECT_FALSE(bytesAllowedByMemoryMax("max\n"));
    EXPECT_FALSE(bytesAllowedByMemoryMax(""));
    EXPECT_FALSE(bytesAllowedByMemoryMax("2G"));
}

TEST(CgroupLimits, TheProcessCgroupIsTheV2Line) {
    EXPECT_EQ(*cgroupV2Path("0::/system.slice/slurmstepd.scope/job_7/step_0\n"),
              "/system.slice/slurmstepd.scope/job_7/step_0");
    EXPECT_EQ(*cgroupV2Path("12:cpu,cpuacct:/x\n0::/\n"), "/");
    EXPECT_FALSE(cgroupV2Path("12:cpu,cpuacct:/x\n4:memory:/x\n"));  // cgroup v1 alone
}

TEST(CgroupLimits, TheTightestLimitOfTheGroupAndItsAncestorsBinds) {
    testing::ScratchFolder root("cgroup");
    writeFile(root / "cpu.max", "max 100000\n");
    writeFile(root / "job/cpu.max", "300000 100000\n");
    writeFile(root / "job/step/cpu.max", "max 100000\n");  // unlimited itself, bound by its parent
    writeFile(root / "job/memory.max", "max\n");
    writeFile(root / "job/step/memory.max", "1073741824\n");
    EXPECT_DOUBLE_EQ(*tightestCgroupLimit(root.path(), "/job/step", "cpu.max", cpusAllowedByCpuMax),
                     3.0);
    EXPECT_EQ(*tightestCgroupLimit(root.path(), "/job/step", "memory.max", bytesAllowedByMemoryMax),
              1073741824u);
    EXPECT_FALSE(tightestCgroupLimit(root.path(), "/", "cpu.max", cpusAllowedByCpuMax));
    EXPECT_FALSE(
        tightestCgroupLimit(root.path(), "/elsewhere", "memory.max", bytesAllowedByMemoryMax));
}

TEST(CgroupLimits, ThreadsAreTheAffinityCappedByTheQuotaRoundedUp) {
    EXPECT_EQ(usableCpus(128, 2.0), 2u);
    EXPECT_EQ(usableCpus(128, 1.5), 2u);
    EXPECT_EQ(usableCpus(128, 0.2), 1u);
    EXPECT_EQ(usableCpus(2, 8.0), 2u);
    EXPECT_EQ(usableCpus(16, std::nullopt), 16u);
    EXPECT_EQ(usableCpus(0, std::nullopt), 1u);
}

TEST(CgroupLimits, TheMemoryLimitIsTheCgroupsWhenLower) {
    EXPECT_EQ(defaultMemoryLimit(64ull << 30, std::nullopt), 32ull << 30);
    EXPECT_EQ(defaultMemoryLimit(64ull << 30, 2ull << 30), 1536ull << 20);  // 3/4 of --mem=2G
    EXPECT_EQ(defaultMemoryLimit(8ull << 30, 100ull << 30), 4ull << 30);
}

// The real executable, bound to one CPU, sizes its pools for one.
TEST(CgroupLimits, TasksetToOneCpuGivesOneThread) {
    const auto bound = testing::runCommand(
        "env -u MATEVO_THREADS taskset -c 0 " +
        testing::shellQuoted(fs::path(MATEVO_BINARY_DIR) / "matevo") + " --version --verbose");
    ASSERT_EQ(bound.exitCode, 0) << bound.err;
    EXPECT_NE(bound.out.find("\nthreads: 1 "), std::string::npos) << bound.out;
}

}  // namespace
}  // namespace matevo
