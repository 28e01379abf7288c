#pragma once
// The memory limit enforced while work runs, where the estimate before it (MemoryBudget.h) may
// be wrong. One thread reads the process's peak resident memory every 25 ms and, once it is
// past the limit, cancels the work's token with CancelReason::MemoryLimit: the work stops at
// its next cancellation point, as on a stop request, and whoever started it reports the limit.
// No allocator hooks: the kernel's own count of resident pages, which is what the OOM killer
// acts on and what `/usr/bin/time -v` reports. The peak, not the resident set of the moment, so
// that a spike between two samples is not missed.
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <thread>

#include "common/CancelToken.h"

namespace matevo {

// The most memory this process has had resident so far, in bytes (getrusage's ru_maxrss).
std::uint64_t peakResidentBytes();

class MemoryWatch {
public:
    // Watches from now until destroyed, cancelling `work` past `limitBytes`.
    MemoryWatch(CancelToken work, std::uint64_t limitBytes);
    ~MemoryWatch();
    MemoryWatch(const MemoryWatch&) = delete;
    MemoryWatch& operator=(const MemoryWatch&) = delete;

    // The peak resident bytes once they passed the limit, nothing while within it. Samples once
    // more, so that at the end of the work a peak since the last sample counts too.
    std::optional<std::uint64_t> exceeded();
    std::uint64_t limitBytes() const { return limit_; }

private:
    std::uint64_t sample();  // the peak
    void watch();

    CancelToken work_;
    const std::uint64_t limit_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stopping_ = false;  // guarded by mutex_
    bool passed_ = false;    // guarded by mutex_
    std::thread thread_;     // last: started once the rest is ready
};

}  // namespace matevo
