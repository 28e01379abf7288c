#pragma once
// The one format of everything matevo says on stderr, and its exit statuses.
//
//   matevo COMMAND: TEXT             an error or a notice ("matevo: TEXT" before a command is
//                                    chosen)
//   matevo COMMAND: warning: TEXT    something the user should know; the command goes on
//
// TEXT is one line and names the file, field or option at fault. Commands never print the
// prefix themselves: they throw UsageError("--out: ...") or call these functions.
#include <string>
#include <string_view>

namespace matevo::cli {

// The documented exit statuses (matevo --help, docs/architecture.md).
enum class ExitStatus : int {
    Success = 0,
    InternalFailure = 1,  // a bug or a failure of the machine (Vulkan, memory): not the user's
    BadUsage = 2,         // bad usage or input: a mistyped option, a bad file, a missing folder
    AboveThreshold = 3,   // compare --fail-above: the difference is above the threshold
    RequestNotMet = 3,    // variants: the set asked for cannot be made (what was found is kept)
};

inline int exitCode(ExitStatus status) { return int(status); }

// main() names the command once it is chosen; every later message carries it.
void setMessageCommand(std::string_view command);
// "matevo COMMAND: " (or "matevo: "), for progress lines that redraw themselves.
std::string messagePrefix();

void printMessage(std::string_view text);
void printWarning(std::string_view text);

}  // namespace matevo::cli
