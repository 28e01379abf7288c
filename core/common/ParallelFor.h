#pragma once
// The one parallel loop of core: fixed chunks of work shared by the calling thread and the
// persistent helpers of common/WorkerPool.h (workerThreadCount() threads in all,
// common/WorkerThreads.h). Chunks are claimed in any order, so work(chunk) must write only its
// own chunk's outputs; then results never depend on the number of threads or on scheduling.
//
// Failure: the first exception thrown by a chunk (or by onProgress) stops the claiming of new
// chunks; the chunks already started run to their end, and then that exception is rethrown on
// the calling thread. Later exceptions are dropped.
//
// Nesting: a loop started inside a chunk that runs on a pool helper runs inline on that helper
// (its chunks in order, with one scratch object), so loops may nest without waiting on one
// another.
#include <functional>
#include <vector>

namespace matevo {

namespace detail {

// How many threads a loop of chunkCount chunks runs on: at most maxThreads (0: as many as
// workerThreadCount()), at most one per chunk, at least 1, and 1 on a pool helper.
int loopThreadCount(int chunkCount, unsigned maxThreads);

// Calls work(thread, chunk) for every chunk in [0, chunkCount), on threadCount threads, each
// given its index in [0, threadCount); the calling thread is thread 0 and reports progress as
// parallelForChunks says.
void runChunks(int chunkCount, int threadCount, const std::function<void(int, int)>& work,
               const std::function<void(int chunksDone)>& onProgress);

}  // namespace detail

// Runs work(chunk) for every chunk in [0, chunkCount) on up to maxThreads threads (0: as many
// as workerThreadCount()). The calling thread works too and, after each chunk it finishes,
// calls onProgress(chunksDoneSoFar) if given; and with chunkCount at the end if it has not yet.
void parallelForChunks(int chunkCount, const std::function<void(int chunk)>& work,
                       const std::function<void(int chunksDone)>& onProgress = {},
                       unsigned maxThreads = 0);

// As parallelForChunks, and each thread of the loop gets one scratch object (makeScratch(),
// called on the calling thread before any chunk runs) that it hands to every
// work(scratch, chunk) it runs, so buffers are reused from chunk to chunk. Returns the
// scratch objects, for what they gathered (which chunks each saw depends on scheduling).
template <typename MakeScratch, typename Work>
auto parallelForChunksWithScratch(int chunkCount, const MakeScratch& makeScratch, const Work& work,
                                  unsigned maxThreads = 0) {
    std::vector<decltype(makeScratch())> scratches;
    if (chunkCount <= 0) return scratches;
    const int threadCount = detail::loopThreadCount(chunkCount, maxThreads);
    for (int i = 0; i < threadCount; ++i) scratches.push_back(makeScratch());
    detail::runChunks(chunkCount, threadCount,
                      [&](int thread, int chunk) { work(scratches[std::size_t(thread)], chunk); },
                      {});
    return scratches;
}

}  // namespace matevo
