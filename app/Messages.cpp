#include "Messages.h"

#include <cstdio>

#include "common/ShortText.h"

namespace matevo::cli {
namespace {

std::string& currentCommand() {
    static std::string command;
    return command;
}

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

}  // namespace matevo::cli
