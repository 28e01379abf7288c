#pragma once
// A bound on the memory one piece of work may take, checked up front against an estimate so
// that large work is refused with a clear message instead of ending in the OOM killer.
// The limit is half the machine's physical memory, or three quarters of the cgroup's
// `memory.max` when that is lower (a batch job's --mem: the OOM killer acts on it, and the
// quarter left is for what an estimate does not count, the program and its drivers), unless the
// program sets another one (the command line's --max-memory) before any work starts.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

#include "common/ByteSize.h"
#include "common/CgroupLimits.h"
#include "common/Result.h"

namespace matevo {

namespace detail {
// 0 means "not set": the default below applies.
inline std::atomic<std::uint64_t> memoryLimitSetting{0};
}  // namespace detail

inline void setMemoryLimitBytes(std::uint64_t bytes) { detail::memoryLimitSetting = bytes; }

// The default limit for `physicalBytes` of memory and a cgroup limit of `cgroupBytes`, if any.
inline std::uint64_t defaultMemoryLimit(std::uint64_t physicalBytes,
                                        std::optional<std::uint64_t> cgroupBytes) {
    const std::uint64_t half = physicalBytes / 2;
    return cgroupBytes ? std::min(half, *cgroupBytes / 4 * 3) : half;
}

inline std::uint64_t memoryLimitBytes() {
    if (const std::uint64_t setting = detail::memoryLimitSetting; setting > 0) return setting;
    static const std::uint64_t byDefault = [] {
        const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
        const std::uint64_t physical =
            pages > 0 && pageSize > 0 ? std::uint64_t(pages) * std::uint64_t(pageSize) : 8ull << 30;
        return defaultMemoryLimit(physical, cgroupMemoryLimit());
    }();
    return byDefault;
}

// `what` says what would need the memory, e.g. "a.png: decoding 20000x20000 pixels".
inline Status checkMemoryEstimate(std::uint64_t bytes, const std::string& what) {
    const std::uint64_t limit = memoryLimitBytes();
    if (bytes <= limit) return Ok{};
    return badInput(what + " needs about " + describeBytes(bytes) +
                    " of memory, more than the limit of " + describeBytes(limit) +
                    " (--max-memory raises it, e.g. --max-memory 32G)");
}

}  // namespace matevo
