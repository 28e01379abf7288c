#pragma once
// One function per subcommand; each lives in its own file in this folder.
#include "CommandLine.h"

namespace matevo::cli {

int runEdit(CommandLine& args);
int runEvolve(CommandLine& args);
int runRender(CommandLine& args);
int runCompare(CommandLine& args);
int runExperiment(CommandLine& args);
int runPresets(CommandLine& args);
int runBench(CommandLine& args);
int runExport(CommandLine& args);
int runVariants(CommandLine& args);
int runMerge(CommandLine& args);
int runScene(CommandLine& args);

}  // namespace matevo::cli
