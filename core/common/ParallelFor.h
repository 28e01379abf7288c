#pragma once
// Fixed chunks on up to workerThreadCount() threads (common/WorkerThreads.h). Each chunk writes only its own output,
// so results never depend on the number of threads or on scheduling.
#include <functional>

namespace matevo {

// Runs work(chunk) for every chunk in [0, chunkCount). The calling thread works too and, after
// each chunk it finishes, calls onProgress(chunksDoneSoFar) if given.
void parallelForChunks(int chunkCount, const std::function<void(int chunk)>& work,
                       const std::function<void(int chunksDone)>& onProgress = {});

}  // namespace matevo
