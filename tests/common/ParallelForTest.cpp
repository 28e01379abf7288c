// The one parallel loop (common/ParallelFor.h) over the persistent pool (common/WorkerPool.h):
// every chunk once, one scratch per thread, the failure rule, progress on the calling thread,
// nested and concurrent loops that end, and helpers that are reused rather than started anew.
#include "common/ParallelFor.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "common/WorkerPool.h"
#include "common/WorkerThreads.h"

namespace matevo {
namespace {

TEST(ParallelFor, RunsEveryChunkOnceWhateverTheThreadCount) {
    for (unsigned threads : {0u, 1u, 2u, 3u, 64u}) {
        std::vector<std::atomic<int>> runs(1000);
        parallelForChunks(
            int(runs.size()), [&](int chunk) { ++runs[std::size_t(chunk)]; }, {}, threads);
        for (std::size_t i = 0; i < runs.size(); ++i) ASSERT_EQ(runs[i], 1) << threads << " " << i;
    }
    parallelForChunks(0, [](int) { FAIL() << "no chunk to run"; });
}

TEST(ParallelFor, GivesEachThreadOneScratchObject) {
    const int chunkCount = 500;
    std::atomic<int> made{0};
    auto scratches = parallelForChunksWithScratch(
        chunkCount, [&] { return std::make_pair(made++, std::vector<int>{}); },
        [](std::pair<int, std::vector<int>>& scratch, int chunk) {
            scratch.second.push_back(chunk);
        });
    ASSERT_GE(scratches.size(), 1u);
    EXPECT_LE(scratches.size(), std::size_t(workerThreadCount()));
    EXPECT_EQ(made, int(scratches.size()));
    std::multiset<int> seen;
    for (const auto& scratch : scratches) seen.insert(scratch.second.begin(), scratch.second.end());
    ASSERT_EQ(seen.size(), std::size_t(chunkCount));
    for (int chunk = 0; chunk < chunkCount; ++chunk) EXPECT_EQ(seen.count(chunk), 1u) << chunk;
    EXPECT_TRUE(parallelForChunksWithScratch(
                    0, [] { return 0; }, [](int&, int) {})
                    .empty());
}

TEST(ParallelFor, RethrowsTheFirstFailureOnTheCallerAfterStartedChunksEnd) {
    std::atomic<int> running{0};
    std::atomic<int> finished{0};
    try {
        parallelForChunks(100000, [&](int chunk) {
            ++running;
            if (chunk == 3) {
                --running;
                throw std::runtime_error("chunk 3 failed");
            }
            ++finished;
            --running;
        });
        FAIL() << "the failure was not rethrown";
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "chunk 3 failed");
    }
    EXPECT_EQ(running, 0) << "every started chunk ended before the rethrow";
    EXPECT_LT(finished, 99999) << "chunks after the failure were still claimed";
    // The pool is still there for the next loop.
    std::atomic<int> count{0};
    parallelForChunks(100, [&](int) { ++count; });
    EXPECT_EQ(count, 100);
}

TEST(ParallelFor, ReportsProgressOnTheCallingThread) {
    const std::thread::id caller = std::this_thread::get_id();
    int last = 0;
    int calls = 0;
    parallelForChunks(
        200, [](int) {},
        [&](int done) {
            EXPECT_EQ(std::this_thread::get_id(), caller);
            EXPECT_GT(done, last);
            EXPECT_LE(done, 200);
            last = done;
            ++calls;
        });
    EXPECT_GT(calls, 0);
    EXPECT_EQ(last, 200) << "the end is reported, whoever ran the last chunks";
}

TEST(ParallelFor, NestedLoopsEnd) {
    std::vector<std::atomic<int>> runs(64 * 64);
    parallelForChunks(64, [&](int outer) {
        parallelForChunks(64, [&](int inner) { ++runs[std::size_t(outer * 64 + inner)]; });
    });
    for (std::size_t i = 0; i < runs.size(); ++i) ASSERT_EQ(runs[i], 1) << i;
}

TEST(ParallelFor, LoopsFromSeveralThreadsAtOnceEachRunEveryChunk) {
    std::vector<std::thread> callers;
    std::vector<int> sums(4, 0);
    for (std::size_t t = 0; t < sums.size(); ++t)
        callers.emplace_back([&sums, t] {
            for (int round = 0; round < 50; ++round) {
                std::vector<int> values(97, 0);
                parallelForChunks(97, [&](int chunk) { values[std::size_t(chunk)] = chunk; });
                for (int value : values) sums[t] += value;
            }
        });
    for (std::thread& caller : callers) caller.join();
    for (int sum : sums) EXPECT_EQ(sum, 50 * 96 * 97 / 2);
}

TEST(ParallelFor, ReusesItsThreads) {
    std::mutex mutex;
    std::set<std::thread::id> threads;
    for (int loop = 0; loop < 20; ++loop)
        parallelForChunks(64, [&](int) {
            std::this_thread::sleep_for(std::chrono::microseconds(100));
            std::lock_guard lock(mutex);
            threads.insert(std::this_thread::get_id());
        });
    EXPECT_LE(threads.size(), std::size_t(workerThreadCount()));
    EXPECT_EQ(WorkerPool::instance().helperCount(), workerThreadCount() - 1);
}

TEST(WorkerPool, SharesWithIdleHelpersAndJoinsThemAtTheEnd) {
    std::atomic<int> participants{0};
    {
        WorkerPool pool(3);
        EXPECT_EQ(pool.helperCount(), 3u);
        std::vector<std::atomic<int>> seen(8);
        pool.share(7, [&](unsigned participant) {
            ++participants;
            ASSERT_LT(participant, 4u) << "no more helpers than the pool has";
            ++seen[participant];
        });
        EXPECT_EQ(seen[0], 1) << "the calling thread always takes part";
        for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_LE(seen[i], 1) << i;
        WorkerPool none(0);
        int calls = 0;
        none.share(5, [&](unsigned participant) {
            EXPECT_EQ(participant, 0u);
            ++calls;
        });
        EXPECT_EQ(calls, 1);
    }  // the destructors join their helpers
    EXPECT_GE(participants, 1);
}

}  // namespace
}  // namespace matevo
