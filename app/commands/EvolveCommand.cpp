#include "commands/Commands.h"

namespace matevo::cli {

int runEvolve(CommandLine& args) {
    (void)args;
    return 1;
}

}  // namespace matevo::cli
