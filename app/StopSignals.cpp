#include "StopSignals.h"

#include <unistd.h>

#include <csignal>

#include "common/StopRequest.h"
#include "files/TemporaryFiles.h"

namespace matevo::cli {

namespace {

// Ends the process with the status the signal itself gives, leaving no temporary file.
void quit(int signal) {
    removeTemporaryFilesInFlight();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

void onStopSignal(int signal) {
    if (stopRequested() != 0) return quit(signal);  // asked twice: stop now
    requestStop(signal);
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

void installStopSignalHandlers() { installHandler(onStopSignal); }

void installQuitSignalHandlers() { installHandler(quit); }

int stoppedExitStatus(int signal) { return 128 + signal; }

std::string signalName(int signal) {
    if (signal == SIGINT) return "SIGINT";
    if (signal == SIGTERM) return "SIGTERM";
    return "signal " + std::to_string(signal);
}

}  // namespace matevo::cli
