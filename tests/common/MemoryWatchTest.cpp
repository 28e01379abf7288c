// The memory watch cancels the work's token, with the memory limit as its reason, once the
// process's resident memory has gone past the limit: also when the memory was given back before
// the watch looked (the peak counts). Limits are set above what this process has had resident
// so far, so that the test holds under AddressSanitizer too, whose shadow memory is resident.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

#include "common/MemoryWatch.h"

namespace matevo {
namespace {

constexpr std::uint64_t kMiB = 1ull << 20;

// Allocates `bytes` in blocks and writes every byte, so that the pages are resident, then gives
// them back; returns the sum of one byte of each block (the writes cannot be left out).
std::uint64_t touchAndRelease(std::uint64_t bytes) {
    constexpr std::size_t kBlock = 4 * kMiB;
    std::vector<std::unique_ptr<char[]>> blocks;
    for (std::uint64_t done = 0; done < bytes; done += kBlock) {
        blocks.emplace_back(new char[kBlock]);
        std::memset(blocks.back().get(), 1, kBlock);
    }
    std::uint64_t sum = 0;
    for (const auto& block : blocks) sum += std::uint64_t(block[kBlock / 2]);
    return sum;
}

// Waits until `work` is cancelled; gives up (the test then fails) after a minute.
void waitForCancellation(const CancelToken& work) {
    const auto giveUp = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (!work.cancelled() && std::chrono::steady_clock::now() < giveUp)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

TEST(MemoryWatch, CancelsTheWorkWithTheMemoryReasonPastTheLimit) {
    const CancelToken work;
    const std::uint64_t limit = peakResidentBytes() + 64 * kMiB;
    MemoryWatch watch(work, limit);
    EXPECT_EQ(watch.limitBytes(), limit);
    std::uint64_t touched = 0;
    std::thread allocating([&touched] { touched = touchAndRelease(96 * kMiB); });
    allocating.join();
    EXPECT_EQ(touched, 96 * kMiB / (4 * kMiB));
    waitForCancellation(work);
    EXPECT_EQ(work.reason(), CancelReason::MemoryLimit);
    const auto resident = watch.exceeded();
    ASSERT_TRUE(resident.has_value());
    EXPECT_GT(*resident, limit);
}

TEST(MemoryWatch, LeavesWorkWithinTheLimitAlone) {
    const CancelToken work;
    MemoryWatch watch(work, peakResidentBytes() + 1024 * kMiB);
    EXPECT_EQ(touchAndRelease(16 * kMiB), 16 * kMiB / (4 * kMiB));
    EXPECT_FALSE(watch.exceeded().has_value());
    EXPECT_FALSE(work.cancelled());
    EXPECT_EQ(work.reason(), CancelReason::None);
}

TEST(MemoryWatch, AStopRequestedEarlierKeepsItsReason) {
    const CancelToken work;
    work.cancel();
    MemoryWatch watch(work, 1);  // every process is past one byte
    EXPECT_TRUE(watch.exceeded().has_value());
    EXPECT_EQ(work.reason(), CancelReason::Request);
}

}  // namespace
}  // namespace matevo
