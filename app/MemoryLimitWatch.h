#pragma once
// --max-memory enforced while a command works, not only estimated before (WorkEstimate.h):
// once a command's estimate has passed, a watch (common/MemoryWatch.h) cancels the process's
// stop token (StopSignals.h) with CancelReason::MemoryLimit when the resident memory goes past
// the limit. The work stops at its next cancellation point: a long command keeps what is
// complete, marked partial, as after SIGINT; a short one writes nothing. Whatever the command
// then returns or throws, its outcome is the limit: one line, and the exit status of an error
// of the environment (1), never success and never a signal's 130/143.
#include <string>

namespace matevo::cli {

class CommandLine;

// Watches the rest of the command; `what` names the work in the message, as the estimate does.
void watchMemoryLimit(const std::string& what);

// Samples the resident memory now (between the watch's samples), so that a check before output
// is written sees a peak reached since the last sample; cancels the stop token when past the
// limit. Nothing while no work is watched.
void sampleMemoryNow();

// Runs `command`; when the memory limit was passed while it worked, throws CommandFailure
// "memory limit 512 MiB exceeded by WHAT (resident 530 MiB)" in place of its outcome.
int runWithinMemoryLimit(int (*command)(CommandLine&), CommandLine& args);

}  // namespace matevo::cli
