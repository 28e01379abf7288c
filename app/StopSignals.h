#pragma once
// SIGINT and SIGTERM during long commands (evolve, experiment, variants): the first cancels the
// process's stop token (common/CancelToken.h), which the command passes into core, so the work
// stops at its next generation or batch and what is complete is written whole and marked
// partial; a second one ends the process at once.
#include <string>

#include "common/CancelToken.h"

namespace matevo::cli {

// The token the commands pass down; cancelled by the first SIGINT or SIGTERM once
// installStopSignalHandlers() ran, and at the memory limit (MemoryLimitWatch.h).
const CancelToken& stopToken();
// The signal that cancelled stopToken(), 0 when none did.
int stopSignal();

void installStopSignalHandlers();
// For short commands (render, scene): SIGINT and SIGTERM end them at once, as by default, but
// first remove the temporary file being written (files/TemporaryFiles.h). The stop handlers above
// do the same when a second signal ends a long command.
void installQuitSignalHandlers();

// A cancellation point of a command with nothing partial to keep (render, scene, compare,
// export): throws CommandFailure once stopToken() is cancelled, for main to report why
// (MemoryLimitWatch.h).
void stopIfCancelled();
// What cancelled stopToken(), for a report marked partial: "SIGINT", "SIGTERM" or
// "memory limit"; empty while nothing did.
std::string stoppedBy();

// 130 for SIGINT, 143 for SIGTERM (128 + signal), as shells report a process the signal ended.
int stoppedExitStatus(int signal);
// "SIGINT" or "SIGTERM".
std::string signalName(int signal);

}  // namespace matevo::cli
