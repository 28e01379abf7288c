#include "Messages.h"

#include <unistd.h>

#include <cstdio>

#include "common/ShortText.h"
#include "common/StatusOutput.h"

namespace matevo::cli {
namespace {

std::string& currentCommand() {
    static std::string command;
    return command;
}

bool quietOutput = false;
bool progressShown = false;  // a progress line is on the terminal, not yet ended

}  // namespace

void setMessageCommand(std::string_view command) { currentCommand() = command; }

std::string messagePrefix() {
    const std::string& command = currentCommand();
    return command.empty() ? std::string("matevo: ") : "matevo " + command + ": ";
}

void printMessage(std::string_view text) {
    std::fprintf(stderr, "%s%s\n", messagePrefix().c_str(), visibleText(text).c_str());
}

void printWarning(std::string_view text) {
    std::fprintf(stderr, "%swarning: %s\n", messagePrefix().c_str(), visibleText(text).c_str());
}

void printNotice(std::string_view text) {
    if (!quietOutput) printMessage(text);
}

void printProgress(std::string_view text) {
    static const bool onTerminal = ::isatty(STDERR_FILENO) != 0;
    if (quietOutput || !onTerminal) return;
    if (text.empty()) {
        if (progressShown) std::fputc('\n', stderr);
        progressShown = false;
        return;
    }
    std::fprintf(stderr, "\r%s%.*s\x1b[K", messagePrefix().c_str(), int(text.size()), text.data());
    progressShown = true;
}

void setQuiet(bool quiet) { quietOutput = quiet; }

bool quiet() { return quietOutput; }

void installStatusSinks() { matevo::setStatusSinks(printNotice, printProgress); }

ExitStatus exitStatusOf(ErrorKind kind) {
    switch (kind) {
        case ErrorKind::BadInput:
            return ExitStatus::BadUsage;
        case ErrorKind::Environment:
        case ErrorKind::Internal:
            return ExitStatus::InternalFailure;
        case ErrorKind::Cancelled:
            return ExitStatus::Interrupted;
    }
    return ExitStatus::InternalFailure;
}

}  // namespace matevo::cli
