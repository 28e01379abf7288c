#pragma once
// The process's CPU helper threads: workerThreadCount() - 1 of them (common/WorkerThreads.h),
// started once, at first use, and kept until exit, so a parallel loop costs a wake-up instead
// of starting threads. Only ParallelFor.h uses it; everything else runs loops through there.
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace matevo {

class WorkerPool {
public:
    // The one pool, started on the first call.
    static WorkerPool& instance();
    // Whether the calling thread is one of the pool's helpers.
    static bool onWorker();

    explicit WorkerPool(unsigned helperCount);
    // Lets the helpers finish what they run and joins them.
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    unsigned helperCount() const { return unsigned(helpers_.size()); }

    // Calls run(0) on the calling thread and run(1), run(2), ... on up to `helpers` helpers
    // that are idle or become so before run(0) returns; returns once every run() started has
    // returned. run must not throw. Helpers busy elsewhere are not waited for, so the calling
    // thread never waits on a run() that has not started.
    void share(unsigned helpers, const std::function<void(unsigned participant)>& run);

private:
    // One share() call; lives on its caller's stack, touched only under mutex_.
    struct Task {
        const std::function<void(unsigned)>* run = nullptr;
        unsigned seatsLeft = 0;        // helpers that may still join
        unsigned nextParticipant = 1;  // 0 is the calling thread
        unsigned running = 0;          // helpers inside run()
        std::condition_variable allReturned;
    };

    void helperLoop();

    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Task*> queue_;  // tasks with seats left
    bool stopping_ = false;
    std::vector<std::thread> helpers_;  // last: started once the members they use exist
};

}  // namespace matevo
