#include "common/WorkerPool.h"

#include <algorithm>

#include "common/WorkerThreads.h"

namespace matevo {
namespace {

thread_local bool isPoolHelper = false;

}  // namespace

WorkerPool& WorkerPool::instance() {
    // Destroyed at exit after main returns, when no loop runs any more.
    static WorkerPool pool(workerThreadCount() - 1);
    return pool;
}

bool WorkerPool::onWorker() { return isPoolHelper; }

WorkerPool::WorkerPool(unsigned helperCount) {
    helpers_.reserve(helperCount);
    for (unsigned i = 0; i < helperCount; ++i) helpers_.emplace_back([this] { helperLoop(); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& helper : helpers_) helper.join();
}

void WorkerPool::helperLoop() {
    isPoolHelper = true;
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
        if (stopping_) return;
        Task& task = *queue_.front();
        const unsigned participant = task.nextParticipant++;
        ++task.running;
        if (--task.seatsLeft == 0) queue_.pop_front();
        lock.unlock();
        (*task.run)(participant);
        lock.lock();
        // Under the lock: the caller, waiting on it, cannot return and end `task` before this.
        if (--task.running == 0) task.allReturned.notify_one();
    }
}

void WorkerPool::share(unsigned helpers, const std::function<void(unsigned participant)>& run) {
    helpers = std::min(helpers, helperCount());
    if (helpers == 0) return run(0);
    Task task;
    task.run = &run;
    task.seatsLeft = helpers;
    {
        std::lock_guard lock(mutex_);
        queue_.push_back(&task);
    }
    if (helpers == 1)
        wake_.notify_one();
    else
        wake_.notify_all();
    run(0);
    std::unique_lock lock(mutex_);
    // Seats no helper took are withdrawn: run(0) has done the work they would have shared.
    if (task.seatsLeft > 0) queue_.erase(std::find(queue_.begin(), queue_.end(), &task));
    task.allReturned.wait(lock, [&task] { return task.running == 0; });
}

}  // namespace matevo
