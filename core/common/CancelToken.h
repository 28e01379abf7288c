#pragma once
// The one way to ask running work to stop early. Whoever starts work keeps a token and passes
// copies into core (experiment, variant search, renderers, export); copies share one flag, so
// cancel() on any of them is seen by all. Loops check cancelled() at their next generation,
// batch or tile boundary, so what is complete can still be written whole.
#include <atomic>
#include <memory>

namespace matevo {

class CancelToken {
public:
    CancelToken() : state_(std::make_shared<std::atomic<bool>>(false)) {}

    void cancel() const { state_->store(true, std::memory_order_relaxed); }
    bool cancelled() const { return state_->load(std::memory_order_relaxed); }

    // The flag itself, for a signal handler: storing to a lock-free atomic is async-signal-safe
    // where touching the shared pointer is not. Valid while any copy of the token lives.
    std::atomic<bool>* flag() const { return state_.get(); }

private:
    std::shared_ptr<std::atomic<bool>> state_;
};

}  // namespace matevo
