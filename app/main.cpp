// matevo: evolve variants of a layered material. Dispatches to one subcommand and maps the kind
// of every failure it throws to the documented exit statuses, once (Messages.h): 0 ok,
// 1 internal or machine failure, 2 bad usage or input, 3 compare --fail-above exceeded, 130 a
// stop request. Every message has the form "matevo COMMAND: TEXT".
#include <csignal>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "CommandLine.h"
#include "MemoryLimitWatch.h"
#include "Messages.h"
#include "Suggestion.h"
#include "commands/Commands.h"
#include "common/MemoryBudget.h"
#include "common/WorkerThreads.h"
#include "documents/PresetCatalog.h"
#include "gpu/LoaderEnvironment.h"

namespace {

using namespace matevo::cli;

struct Subcommand {
    std::string_view name;
    int (*run)(CommandLine&);
    std::string_view summary;
    bool takesMaxMemory;  // reads images or renders: work whose memory --max-memory bounds
};

// One line per subcommand; `matevo --help` lists them in this order.
constexpr Subcommand kSubcommands[] = {
    {"edit", runEdit, "open the editor (default; PRESET defaults to validation metal)", true},
    {"evolve", runEvolve, "run the genetic algorithm on a preset's target material", true},
    {"render", runRender, "render one material on the test sphere to PNG or EXR", true},
    {"compare", runCompare, "per-pixel CIEDE2000 between two images", true},
    {"experiment", runExperiment, "the paper's section 5 experiment: metrics x runs", true},
    {"variants", runVariants, "N variants a chosen perceptible difference from the target", true},
    {"merge", runMerge, "join the shares of a variants --shard run into one set", false},
    {"presets", runPresets, "list the presets --preset NAME accepts (shipped and your own)", false},
    {"bench", runBench, "measure the GA, CIEDE2000 and renderers; medians", false},
    {"export", runExport, "write materials for engines (glTF, MaterialX), fitted by dE00", true},
    {"scene", runScene, "render many instances of a mesh, one variant each, to PNG or EXR", true},
};

constexpr const char* kMaxMemoryHelp =
    "  --max-memory SIZE  refuse work whose estimated memory is past SIZE, and stop work\n"
    "                     whose resident memory passes it (exit 1) (e.g. 512M, 16G;\n"
    "                     default half the machine's memory, or 3/4 of the cgroup's\n"
    "                     memory.max when lower); every command that reads images or\n"
    "                     renders takes it\n";

void printHelp() {
    std::printf(
        "matevo - evolve many variants of a layered material (Belcour 2018 BSDF, genetic\n"
        "algorithm of Bernardi et al. 2020).\n\n"
        "usage: matevo [COMMAND] [ARGS...]\n"
        "       matevo --version [--verbose] | --help | help COMMAND\n\n"
        "commands:\n");
    for (const auto& sub : kSubcommands)
        std::printf("  %-11.*s %.*s\n", int(sub.name.size()), sub.name.data(),
                    int(sub.summary.size()), sub.summary.data());
    std::printf(
        "\n'matevo COMMAND --help' describes a command. With no command, or with a preset file\n"
        "as the only argument, matevo opens the editor.\n"
        "messages: 'matevo COMMAND: TEXT' on stderr, one line each; progress is redrawn in place\n"
        "          only on a terminal; every command takes --quiet, which leaves only errors,\n"
        "          warnings and the outcome.\n"
        "exit status: 0 success, 1 internal failure or the memory limit passed while working,\n"
        "             2 bad usage or input, 3 compare --fail-above: the difference is above\n"
        "             the threshold.\n\n%s",
        kMaxMemoryHelp);
}

const Subcommand* findSubcommand(std::string_view name) {
    for (const auto& sub : kSubcommands)
        if (sub.name == name) return &sub;
    return nullptr;
}

[[noreturn]] void unknownCommand(const std::string& word) {
    std::vector<std::string> names;
    for (const auto& sub : kSubcommands) names.emplace_back(sub.name);
    throw UsageError("unknown command '" + word + "'" + didYouMean(word, names) +
                     "; see matevo --help");
}

// A first argument that is not a command opens the editor when it is an option or names a
// preset file; anything else is a mistyped command, not a preset.
bool opensEditor(const std::string& first) {
    std::error_code error;
    return first.rfind('-', 0) == 0 || matevo::looksLikePresetPath(first) ||
           std::filesystem::is_regular_file(first, error);
}

int dispatch(std::vector<std::string> args) {
    if (!args.empty() && args[0] == "--version") {
        std::printf("matevo %s\n", MATEVO_VERSION);
        // What this process may use here, e.g. inside a batch job's allocation.
        if (args.size() > 1 && args[1] == "--verbose")
            std::printf(
                "threads: %u (CPUs this process may use: %u; MATEVO_THREADS sets it)\n"
                "memory limit: %s (--max-memory sets it)\n",
                matevo::workerThreadCount(), matevo::usableCpusOfProcess(),
                matevo::describeBytes(matevo::memoryLimitBytes()).c_str());
        return exitCode(ExitStatus::Success);
    }
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h" || args[0] == "help")) {
        if (args.size() == 1 || args[0] != "help") {
            printHelp();
            return exitCode(ExitStatus::Success);
        }
        args = {args[1], "--help"};  // "matevo help COMMAND"
    }
    const Subcommand* chosen = findSubcommand("edit");
    if (!args.empty()) {
        if (const Subcommand* named = findSubcommand(args[0])) {
            chosen = named;
            args.erase(args.begin());
        } else if (!opensEditor(args[0])) {
            unknownCommand(args[0]);
        }
    }
    setMessageCommand(chosen->name);
    CommandLine commandLine(std::string(chosen->name), std::move(args));
    setQuiet(commandLine.flag("--quiet"));
    if (!chosen->takesMaxMemory) return chosen->run(commandLine);
    if (const auto limit = commandLine.option("--max-memory"))
        matevo::setMemoryLimitBytes(parseByteSizeOption(*limit, "--max-memory"));
    const int status = runWithinMemoryLimit(chosen->run, commandLine);
    if (commandLine.wantsHelp()) std::printf("\n%s", kMaxMemoryHelp);
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    // Past a file size limit (ulimit -f) a write must fail with EFBIG, reported as an error
    // (exit 2, no partial file), instead of SIGXFSZ ending the process.
    std::signal(SIGXFSZ, SIG_IGN);
#ifdef __GLIBC__
    // Every evaluation of a grid allocates and frees tens of megabytes of images. By default
    // glibc maps large blocks one by one and hands freed memory back to the kernel, so each
    // evaluation paid for page faults and zeroed pages again (~15 % of the GPU grid's CPU
    // time on lavapipe, docs/gpu-performance.md): keep up to 128 MiB of freed memory instead.
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 128 << 20);
#endif
    matevo::gpu::prepareVulkanEnvironment();
    installStatusSinks();
    try {
        return dispatch(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const CommandFailure& failure) {
        // A bug says so; every other failure's message already names what went wrong.
        const bool bug = failure.kind == matevo::ErrorKind::Internal;
        printMessage((bug ? std::string("internal error: ") : std::string()) + failure.what());
        return exitCode(exitStatusOf(failure.kind));
    } catch (const std::bad_alloc&) {
        printMessage("out of memory");
        return exitCode(exitStatusOf(matevo::ErrorKind::Environment));
    } catch (const std::exception& error) {
        printMessage(std::string("internal error: ") + error.what());
        return exitCode(ExitStatus::InternalFailure);
    }
}
