#include <cstdio>

#include "commands/Commands.h"

namespace matevo::cli {

// Placeholder until the issue that owns 'matevo compare' lands.
int runCompare(CommandLine& args) {
    (void)args;
    std::fprintf(stderr, "matevo compare: not available in this build yet\n");
    return 1;
}

}  // namespace matevo::cli
