#pragma once
// Fixed chunks of work on up to workerCount threads (0: workerThreadCount()), shared by the
// image comparisons. Chunks are claimed in any order, so work(chunk) must write only to its own
// chunk's outputs; then results never depend on the thread count.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

#include "common/WorkerThreads.h"

namespace matevo::detail {

// As forEachChunk, and each worker makes one scratch object (makeScratch()) that it hands to
// every work(scratch, chunk) it runs, so that buffers are reused from chunk to chunk. Returns
// the workers' scratch objects, for what they gathered.
template <typename MakeScratch, typename Work>
auto forEachChunkWithScratch(std::size_t chunkCount, unsigned workerCount,
                             const MakeScratch& makeScratch, const Work& work) {
    std::vector<decltype(makeScratch())> scratches;
    if (chunkCount == 0) return scratches;
    unsigned workers = workerCount != 0 ? workerCount : workerThreadCount();
    workers = unsigned(std::clamp<std::size_t>(workers, 1, chunkCount));
    for (unsigned i = 0; i < workers; ++i) scratches.push_back(makeScratch());
    std::atomic<std::size_t> next{0};
    auto drain = [&](auto& scratch) {
        for (std::size_t chunk = next++; chunk < chunkCount; chunk = next++) work(scratch, chunk);
    };
    {
        std::vector<std::jthread> helpers;
        for (unsigned i = 1; i < workers; ++i) helpers.emplace_back([&, i] { drain(scratches[i]); });
        drain(scratches[0]);
    }  // joins the helpers
    return scratches;
}

template <typename Work>
void forEachChunk(std::size_t chunkCount, unsigned workerCount, const Work& work) {
    forEachChunkWithScratch(
        chunkCount, workerCount, [] { return 0; }, [&](int, std::size_t chunk) { work(chunk); });
}

}  // namespace matevo::detail
