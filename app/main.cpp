// matevo: evolve variants of a layered material. Dispatches to one subcommand; maps failures to
// the exit statuses of the command-line contract (0 ok, 2 bad usage or input, 1 internal).
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "CommandLine.h"
#include "commands/Commands.h"

namespace {

using namespace matevo::cli;

struct Subcommand {
    std::string_view name;
    int (*run)(CommandLine&);
    std::string_view summary;
};

constexpr Subcommand kSubcommands[] = {
    {"edit", runEdit, "open the editor (default; PRESET defaults to validation metal)"},
    {"evolve", runEvolve, "run the genetic algorithm on a preset's target material"},
    {"render", runRender, "render one material on the test sphere to PNG or EXR"},
    {"compare", runCompare, "per-pixel CIEDE2000 between two images"},
    {"experiment", runExperiment, "the paper's section 5 experiment: metrics x runs"},
    {"variants", runVariants, "N variants a chosen perceptible difference from the target"},
    {"bench", runBench, "measure the GA, CIEDE2000 and renderers; medians"},
};

void printHelp() {
    std::printf(
        "matevo - evolve many variants of a layered material (Belcour 2018 BSDF, genetic\n"
        "algorithm of Bernardi et al. 2020).\n\n"
        "usage: matevo [COMMAND] [ARGS...]\n\n"
        "commands:\n");
    for (const auto& sub : kSubcommands)
        std::printf("  %-11.*s %.*s\n", int(sub.name.size()), sub.name.data(),
                    int(sub.summary.size()), sub.summary.data());
    std::printf(
        "\n'matevo COMMAND --help' describes a command. With no command, or with a preset file\n"
        "as the only argument, matevo opens the editor.\n"
        "exit status: 0 success, 2 bad usage or input, 1 internal failure.\n");
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h" || args[0] == "help")) {
        printHelp();
        return 0;
    }
    const Subcommand* chosen = &kSubcommands[0];  // editor by default
    if (!args.empty()) {
        for (const auto& sub : kSubcommands) {
            if (args[0] == sub.name) {
                chosen = &sub;
                args.erase(args.begin());
                break;
            }
        }
    }
    try {
        CommandLine commandLine(std::string(chosen->name), std::move(args));
        return chosen->run(commandLine);
    } catch (const UsageError& error) {
        std::fprintf(stderr, "matevo: %s\n", error.what());
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "matevo: internal error: %s\n", error.what());
        return 1;
    }
}
