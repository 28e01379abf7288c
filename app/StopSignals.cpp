#include "StopSignals.h"

#include <unistd.h>

#include <atomic>
#include <csignal>

#include "CommandLine.h"
#include "MemoryLimitWatch.h"
#include "files/TemporaryFiles.h"

namespace matevo::cli {

namespace {

// What the handler touches: only lock-free atomics (async-signal-safe), never the token's
// shared pointer. Set before the handlers are installed.
CancelToken::State* stopState = nullptr;
std::atomic<int> stopSignalNumber{0};

// Ends the process with the status the signal itself gives, leaving no temporary file.
void quit(int signal) {
    removeTemporaryFilesInFlight();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

void onStopSignal(int signal) {
    if (stopSignalNumber.load(std::memory_order_relaxed) != 0)
        return quit(signal);  // asked twice: stop now
    stopSignalNumber.store(signal, std::memory_order_relaxed);
    CancelToken::cancelState(*stopState, CancelReason::Request);
    constexpr char kNotice[] =
        "\nmatevo: stopping after the current step and keeping what is complete "
        "(again to quit at once)\n";
    (void)!::write(STDERR_FILENO, kNotice, sizeof kNotice - 1);
}

void installHandler(void (*handler)(int)) {
    struct sigaction action {};
    action.sa_handler = handler;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

const CancelToken& stopToken() {
    static const CancelToken token;
    return token;
}

int stopSignal() { return stopSignalNumber.load(std::memory_order_relaxed); }

void installStopSignalHandlers() {
    stopState = stopToken().state();
    installHandler(onStopSignal);
}

void installQuitSignalHandlers() { installHandler(quit); }

void stopIfCancelled() {
    sampleMemoryNow();  // a peak since the watch's last sample counts before anything is written
    if (stopToken().cancelled()) throw CommandFailure(cancelledError());
}

std::string stoppedBy() {
    switch (stopToken().reason()) {
        case CancelReason::None:
            return {};
        case CancelReason::Request:
            return signalName(stopSignal());
        case CancelReason::MemoryLimit:
            return "memory limit";
    }
    return {};
}

int stoppedExitStatus(int signal) { return 128 + signal; }

std::string signalName(int signal) {
    if (signal == SIGINT) return "SIGINT";
    if (signal == SIGTERM) return "SIGTERM";
    return "signal " + std::to_string(signal);
}

}  // namespace matevo::cli
