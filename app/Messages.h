#pragma once
// The one format of everything matevo says on stderr, and its exit statuses.
//
//   matevo COMMAND: TEXT             an error or a notice ("matevo: TEXT" before a command is
//                                    chosen)
//   matevo COMMAND: warning: TEXT    something the user should know; the command goes on
//
// TEXT is one line and names the file, field or option at fault. Commands never print the
// prefix themselves: they throw UsageError("--out: ...") or CommandFailure(error), or call
// these functions.
//
// Notices (what a command is doing, e.g. building tables or resuming) and progress are for the
// person watching: progress is redrawn in place only when stderr is a terminal (a log gets the
// notices, one line each, and no `\r` updates), and --quiet silences both. Errors, warnings and
// the outcome of a command are always said.
#include <string>
#include <string_view>

#include "common/Result.h"

namespace matevo::cli {

// The documented exit statuses (matevo --help, docs/architecture.md).
enum class ExitStatus : int {
    Success = 0,
    InternalFailure = 1,  // a bug or a failure of the machine (Vulkan, memory, the memory limit
                          // passed while working): not the user's
    BadUsage = 2,         // bad usage or input: a mistyped option, a bad file, a missing folder
    AboveThreshold = 3,   // compare --fail-above: the difference is above the threshold
    RequestNotMet = 3,    // variants: the set asked for cannot be made (what was found is kept)
    Interrupted = 130,    // stopped by SIGINT (128 + 2; SIGTERM's 143 is StopSignals.h's)
};

inline int exitCode(ExitStatus status) { return int(status); }

// The one mapping from where a failure was born (common/Result.h) to the exit status; main()
// applies it to every failure a command throws.
ExitStatus exitStatusOf(ErrorKind kind);

// main() names the command once it is chosen; every later message carries it.
void setMessageCommand(std::string_view command);
// "matevo COMMAND: " (or "matevo: "), for progress lines that redraw themselves.
std::string messagePrefix();

void printMessage(std::string_view text);
void printWarning(std::string_view text);
// A notice: printMessage unless --quiet.
void printNotice(std::string_view text);
// A progress line, redrawn in place on a terminal and not shown otherwise or with --quiet; an
// empty text ends it.
void printProgress(std::string_view text);

// --quiet; also routes core's notices and progress (common/StatusOutput.h) through the two above.
void setQuiet(bool quiet);
bool quiet();
void installStatusSinks();

}  // namespace matevo::cli
