#include "StopSignals.h"

#include <unistd.h>

#include <csignal>

#include "common/StopRequest.h"

namespace matevo::cli {

namespace {

void onStopSignal(int signal) {
    if (stopRequested() != 0) {
        // Asked twice: stop now, with the status the signal itself gives.
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
    }
    requestStop(signal);
    constexpr char kNotice[] =
        "\nmatevo: stopping after the current step and keeping what is complete "
        "(again to quit at once)\n";
    (void)!::write(STDERR_FILENO, kNotice, sizeof kNotice - 1);
}

}  // namespace

void installStopSignalHandlers() {
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

int stoppedExitStatus(int signal) { return 128 + signal; }

std::string signalName(int signal) {
    if (signal == SIGINT) return "SIGINT";
    if (signal == SIGTERM) return "SIGTERM";
    return "signal " + std::to_string(signal);
}

}  // namespace matevo::cli
