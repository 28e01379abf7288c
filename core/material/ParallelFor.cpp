#include "material/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace matevo {

void parallelForChunks(int chunkCount, const std::function<void(int chunk)>& work,
                       const std::function<void(int chunksDone)>& onProgress) {
    std::atomic<int> nextChunk{0};
    std::atomic<int> chunksDone{0};
    auto runChunks = [&](bool reportProgress) {
        for (int chunk = nextChunk++; chunk < chunkCount; chunk = nextChunk++) {
            work(chunk);
            const int done = ++chunksDone;
            if (reportProgress && onProgress) onProgress(done);
        }
    };
    const int threadCount =
        std::clamp(int(std::thread::hardware_concurrency()), 1, std::max(chunkCount, 1));
    std::vector<std::jthread> helpers;
    for (int i = 1; i < threadCount; ++i) helpers.emplace_back(runChunks, false);
    runChunks(true);
}

}  // namespace matevo
