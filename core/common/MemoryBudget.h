#pragma once
// A bound on the memory one piece of work may take, checked up front against an estimate so
// that large work is refused with a clear message instead of ending in the OOM killer.
// The limit is half the machine's physical memory unless the program sets another one (the
// command line's --max-memory) before any work starts.
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <string>

#include "common/ByteSize.h"
#include "common/Result.h"

namespace matevo {

namespace detail {
// 0 means "not set": the default below applies.
inline std::atomic<std::uint64_t> memoryLimitSetting{0};
}  // namespace detail

inline void setMemoryLimitBytes(std::uint64_t bytes) { detail::memoryLimitSetting = bytes; }

inline std::uint64_t memoryLimitBytes() {
    if (const std::uint64_t setting = detail::memoryLimitSetting; setting > 0) return setting;
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages > 0 && pageSize > 0) return std::uint64_t(pages) * std::uint64_t(pageSize) / 2;
    return 4ull << 30;
}

// `what` says what would need the memory, e.g. "a.png: decoding 20000x20000 pixels".
inline Status checkMemoryEstimate(std::uint64_t bytes, const std::string& what) {
    const std::uint64_t limit = memoryLimitBytes();
    if (bytes <= limit) return Ok{};
    return Error{what + " needs about " + describeBytes(bytes) +
                 " of memory, more than the limit of " + describeBytes(limit) +
                 " (--max-memory raises it, e.g. --max-memory 32G)"};
}

}  // namespace matevo
