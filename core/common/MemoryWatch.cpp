#include "common/MemoryWatch.h"

#include <sys/resource.h>

#include <chrono>

namespace matevo {

namespace {
// Often enough that work stops within a few tens of megabytes of a steady climb; a sample is
// one system call.
constexpr std::chrono::milliseconds kSampleInterval{25};
}  // namespace

std::uint64_t peakResidentBytes() {
    struct rusage usage {};
    if (::getrusage(RUSAGE_SELF, &usage) != 0) return 0;
    return std::uint64_t(usage.ru_maxrss) * 1024;  // kilobytes on Linux
}

MemoryWatch::MemoryWatch(CancelToken work, std::uint64_t limitBytes)
    : work_(std::move(work)), limit_(limitBytes), thread_([this] { watch(); }) {}

MemoryWatch::~MemoryWatch() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

std::optional<std::uint64_t> MemoryWatch::exceeded() {
    const std::uint64_t peak = sample();
    const std::lock_guard lock(mutex_);
    if (!passed_) return std::nullopt;
    return peak;
}

std::uint64_t MemoryWatch::sample() {
    const std::uint64_t peak = peakResidentBytes();
    if (peak > limit_) {
        {
            const std::lock_guard lock(mutex_);
            passed_ = true;
        }
        work_.cancel(CancelReason::MemoryLimit);
    }
    return peak;
}

void MemoryWatch::watch() {
    std::unique_lock lock(mutex_);
    while (!stopping_) {
        lock.unlock();
        sample();
        lock.lock();
        wake_.wait_for(lock, kSampleInterval, [this] { return stopping_; });
    }
}

}  // namespace matevo
