#include <cstdio>

#include "commands/Commands.h"

namespace matevo::cli {

// Placeholder until the issue that owns 'matevo render' lands.
int runRender(CommandLine& args) {
    (void)args;
    std::fprintf(stderr, "matevo render: not available in this build yet\n");
    return 1;
}

}  // namespace matevo::cli
