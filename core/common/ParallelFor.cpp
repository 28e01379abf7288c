#include "common/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "common/WorkerThreads.h"

namespace matevo {

void parallelForChunks(int chunkCount, const std::function<void(int chunk)>& work,
                       const std::function<void(int chunksDone)>& onProgress) {
    std::atomic<int> nextChunk{0};
    std::atomic<int> chunksDone{0};
    // An exception must not escape a helper thread (that would end the process): the first
    // one stops the remaining chunks and is rethrown on the calling thread.
    std::mutex failureMutex;
    std::exception_ptr failure;
    auto runChunks = [&](bool reportProgress) {
        try {
            for (int chunk = nextChunk++; chunk < chunkCount; chunk = nextChunk++) {
                work(chunk);
                const int done = ++chunksDone;
                if (reportProgress && onProgress) onProgress(done);
            }
        } catch (...) {
            nextChunk.store(chunkCount);
            std::lock_guard lock(failureMutex);
            if (!failure) failure = std::current_exception();
        }
    };
    const int threadCount =
        std::clamp(int(workerThreadCount()), 1, std::max(chunkCount, 1));
    {
        std::vector<std::jthread> helpers;
        for (int i = 1; i < threadCount; ++i) helpers.emplace_back(runChunks, false);
        runChunks(true);
    }
    if (failure) std::rethrow_exception(failure);
}

}  // namespace matevo
