#pragma once
// A request to stop long work early (SIGINT or SIGTERM), checked by loops at their next
// generation or batch boundary so that what is complete can still be written whole.
// Async-signal-safe: the handler only stores to a lock-free atomic.
#include <atomic>

namespace matevo {

inline std::atomic<int> stopRequestSignal{0};

// The signal that asked to stop, 0 when none did.
inline int stopRequested() { return stopRequestSignal.load(std::memory_order_relaxed); }
inline void requestStop(int signal) { stopRequestSignal.store(signal, std::memory_order_relaxed); }

}  // namespace matevo
