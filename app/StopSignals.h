#pragma once
// SIGINT and SIGTERM during long commands (evolve, experiment): the first asks the work to stop
// at its next generation or batch (common/StopRequest.h), so what is complete is written whole
// and marked partial; a second one ends the process at once.
#include <string>

namespace matevo::cli {

void installStopSignalHandlers();
// For short commands (render, scene): SIGINT and SIGTERM end them at once, as by default, but
// first remove the temporary file being written (files/TemporaryFiles.h). The stop handlers above
// do the same when a second signal ends a long command.
void installQuitSignalHandlers();

// 130 for SIGINT, 143 for SIGTERM (128 + signal), as shells report a process the signal ended.
int stoppedExitStatus(int signal);
// "SIGINT" or "SIGTERM".
std::string signalName(int signal);

}  // namespace matevo::cli
