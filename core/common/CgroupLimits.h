#pragma once
// What the scheduler lets this process use, beyond what the machine has: the CPUs of its
// affinity mask (taskset, Slurm's --cpus-per-task with task binding) and the limits of its
// cgroup v2 (`cpu.max`, a CPU quota; `memory.max`). A batch job on a 128-core node given 2 CPUs
// must size its thread pools for 2 (WorkerThreads.h) and refuse work past its memory (not the
// node's) before the OOM killer ends it (MemoryBudget.h).
//
// The parsers take the files' text and the readers a cgroup root folder, so tests run them on
// files of their own.
#include <sched.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>

namespace matevo {

// cgroup v2 `cpu.max`, "QUOTA PERIOD" (microseconds) or "max PERIOD": how many CPUs' time the
// group may take (QUOTA / PERIOD, e.g. 1.5); nullopt when unlimited or not understood.
inline std::optional<double> cpusAllowedByCpuMax(std::string_view text) {
    std::istringstream in{std::string(text)};
    std::string quota;
    double period = 0;
    if (!(in >> quota >> period) || quota == "max" || !(period > 0)) return std::nullopt;
    char* end = nullptr;
    const double microseconds = std::strtod(quota.c_str(), &end);
    if (end == quota.c_str() || *end != '\0' || !(microseconds > 0)) return std::nullopt;
    return microseconds / period;
}

// cgroup v2 `memory.max`, bytes or "max"; nullopt when unlimited or not understood.
inline std::optional<std::uint64_t> bytesAllowedByMemoryMax(std::string_view text) {
    std::istringstream in{std::string(text)};
    std::string value;
    if (!(in >> value) || value == "max") return std::nullopt;
    char* end = nullptr;
    const unsigned long long bytes = std::strtoull(value.c_str(), &end, 10);
    if (end == value.c_str() || *end != '\0' || bytes == 0) return std::nullopt;
    return std::uint64_t(bytes);
}

// The process's cgroup v2 path, from the text of /proc/self/cgroup (its "0::/PATH" line);
// nullopt under cgroup v1 alone.
inline std::optional<std::string> cgroupV2Path(std::string_view procSelfCgroup) {
    std::istringstream in{std::string(procSelfCgroup)};
    for (std::string line; std::getline(in, line);)
        if (line.rfind("0::", 0) == 0) return line.substr(3);
    return std::nullopt;
}

// The tightest value `parse` finds in `file` of the cgroup `path` and of each of its ancestors
// up to `root` (the cgroup2 mount, /sys/fs/cgroup): a parent's limit binds its children too.
template <class Parse>
auto tightestCgroupLimit(const std::filesystem::path& root, const std::string& path,
                         const char* file, Parse parse) -> decltype(parse(std::string_view())) {
    decltype(parse(std::string_view())) tightest;
    std::filesystem::path group = root;
    auto consider = [&] {
        std::ifstream in(group / file);
        const std::string text{std::istreambuf_iterator<char>(in), {}};
        if (auto limit = parse(text); limit && (!tightest || *limit < *tightest)) tightest = limit;
    };
    consider();
    for (const auto& part : std::filesystem::path(path).relative_path()) {
        if (part.empty() || part == "." || part == "..") continue;
        group /= part;
        consider();
    }
    return tightest;
}

inline std::optional<std::string> ownCgroupPath() {
    std::ifstream in("/proc/self/cgroup");
    return cgroupV2Path(std::string{std::istreambuf_iterator<char>(in), {}});
}

// The CPUs the cgroup's quota allows this process, nullopt when none is set.
inline std::optional<double> cgroupCpuLimit(const std::filesystem::path& root = "/sys/fs/cgroup") {
    const auto path = ownCgroupPath();
    if (!path) return std::nullopt;
    return tightestCgroupLimit(root, *path, "cpu.max", cpusAllowedByCpuMax);
}

// The cgroup's memory limit of this process, nullopt when none is set.
inline std::optional<std::uint64_t> cgroupMemoryLimit(
    const std::filesystem::path& root = "/sys/fs/cgroup") {
    const auto path = ownCgroupPath();
    if (!path) return std::nullopt;
    return tightestCgroupLimit(root, *path, "memory.max", bytesAllowedByMemoryMax);
}

// The CPUs of `affinity` limited by a quota of `quotaCpus` (rounded up: 1.5 CPUs of time keep
// two threads busy part of the time), at least 1.
inline unsigned usableCpus(unsigned affinity, std::optional<double> quotaCpus) {
    unsigned cpus = std::max(affinity, 1u);
    if (quotaCpus) cpus = std::min(cpus, unsigned(std::max(1.0, std::ceil(*quotaCpus))));
    return cpus;
}

// The CPUs this process may use: its affinity mask and its cgroup's quota.
inline unsigned usableCpusOfProcess() {
    cpu_set_t set;
    CPU_ZERO(&set);
    unsigned affinity = std::thread::hardware_concurrency();
    if (::sched_getaffinity(0, sizeof set, &set) == 0) affinity = unsigned(CPU_COUNT(&set));
    return usableCpus(affinity, cgroupCpuLimit());
}

}  // namespace matevo
