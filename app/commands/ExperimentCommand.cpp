#include <cstdio>

#include "commands/Commands.h"

namespace matevo::cli {

// Placeholder until the issue that owns 'matevo experiment' lands.
int runExperiment(CommandLine& args) {
    (void)args;
    std::fprintf(stderr, "matevo experiment: not available in this build yet\n");
    return 1;
}

}  // namespace matevo::cli
