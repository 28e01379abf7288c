#pragma once
// The one way to ask running work to stop early. Whoever starts work keeps a token and passes
// copies into core (experiment, variant search, renderers, export); copies share one state, so
// cancel() on any of them is seen by all. Loops check cancelled() at their next generation,
// batch or tile boundary, so what is complete can still be written whole.
//
// The token also says why it was cancelled: the work stops the same way either way, but whoever
// started it reports a stop request (exit 130/143) differently from work stopped at the memory
// limit (common/MemoryWatch.h; an error of the environment, exit 1). The first reason stays.
#include <atomic>
#include <memory>

namespace matevo {

enum class CancelReason : int {
    None,         // not cancelled
    Request,      // asked to stop: SIGINT, SIGTERM, the editor closing or superseding a job
    MemoryLimit,  // the process's resident memory went past the memory limit
};

class CancelToken {
public:
    using State = std::atomic<CancelReason>;
    static_assert(State::is_always_lock_free, "set from a signal handler");

    CancelToken() : state_(std::make_shared<State>(CancelReason::None)) {}

    void cancel(CancelReason why = CancelReason::Request) const { cancelState(*state_, why); }
    bool cancelled() const { return reason() != CancelReason::None; }
    CancelReason reason() const { return state_->load(std::memory_order_relaxed); }

    // The state itself, for a signal handler (which calls cancelState on it): a compare-and-swap
    // on a lock-free atomic is async-signal-safe where touching the shared pointer is not.
    // Valid while any copy of the token lives.
    State* state() const { return state_.get(); }

    // Cancels `state` for `why` unless it is cancelled already.
    static void cancelState(State& state, CancelReason why) {
        CancelReason notYet = CancelReason::None;
        state.compare_exchange_strong(notYet, why, std::memory_order_relaxed);
    }

private:
    std::shared_ptr<State> state_;
};

}  // namespace matevo
