#include "common/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>

#include "common/WorkerPool.h"
#include "common/WorkerThreads.h"

namespace matevo {
namespace detail {

int loopThreadCount(int chunkCount, unsigned maxThreads) {
    if (chunkCount <= 1 || WorkerPool::onWorker()) return 1;
    const unsigned wanted = maxThreads != 0 ? maxThreads : workerThreadCount();
    return std::clamp(int(std::min(wanted, WorkerPool::instance().helperCount() + 1)), 1,
                      chunkCount);
}

void runChunks(int chunkCount, int threadCount, const std::function<void(int, int)>& work,
               const std::function<void(int chunksDone)>& onProgress) {
    std::atomic<int> nextChunk{0};
    std::atomic<int> chunksDone{0};
    // An exception must not escape a helper (that would end the process): the first one stops
    // the claiming of chunks and is rethrown here once every started chunk has ended.
    std::mutex failureMutex;
    std::exception_ptr failure;
    int reported = 0;  // the calling thread's last progress
    auto report = [&](int done) {
        if (!onProgress || done <= reported) return;
        reported = done;
        onProgress(done);
    };
    const std::function<void(unsigned)> drain = [&](unsigned thread) {
        try {
            for (int chunk = nextChunk++; chunk < chunkCount; chunk = nextChunk++) {
                work(int(thread), chunk);
                const int done = ++chunksDone;
                if (thread == 0) report(done);
            }
        } catch (...) {
            nextChunk.store(chunkCount);
            std::lock_guard lock(failureMutex);
            if (!failure) failure = std::current_exception();
        }
    };
    if (threadCount <= 1)
        drain(0);
    else
        WorkerPool::instance().share(unsigned(threadCount - 1), drain);
    if (failure) std::rethrow_exception(failure);
    report(chunkCount);  // the helpers may have ended the last chunks, or all of them
}

}  // namespace detail

void parallelForChunks(int chunkCount, const std::function<void(int chunk)>& work,
                       const std::function<void(int chunksDone)>& onProgress, unsigned maxThreads) {
    detail::runChunks(
        chunkCount, detail::loopThreadCount(chunkCount, maxThreads),
        [&](int, int chunk) { work(chunk); }, onProgress);
}

}  // namespace matevo
