#include <cstdio>

#include "commands/Commands.h"

namespace matevo::cli {

// Placeholder until the issue that owns 'matevo edit' lands.
int runEdit(CommandLine& args) {
    (void)args;
    std::fprintf(stderr, "matevo edit: not available in this build yet\n");
    return 1;
}

}  // namespace matevo::cli
