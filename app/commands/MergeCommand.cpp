#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "Messages.h"
#include "commands/Commands.h"
#include "files/OutputFolder.h"
#include "variants/ShardMerge.h"

namespace matevo::cli {
namespace {

constexpr const char* kHelp =
    "usage: matevo merge SHARE_DIR... --out DIR [--force] [--json]\n\n"
    "Joins the folders of `matevo variants ... --block B --shard I/K --out SHARE_DIR` runs (all\n"
    "K of them, in any order) into DIR: byte for byte the files that one run of the same\n"
    "request without --shard writes, with one report. The shares must come from one request\n"
    "(preset, count, block, band, distance, seed, image sizes) and one back end; otherwise\n"
    "nothing is written (exit 2). docs/batch.md shows it after a Slurm job array and GNU\n"
    "parallel.\n"
    "  --out DIR   the joined set; DIR always holds one whole run, never a mix\n"
    "  --force     replace DIR when it holds an earlier matevo output\n"
    "  --json      print the joined report as JSON\n"
    "Exit status 3 when the joined set does not meet the request (as `matevo variants`).\n";

}  // namespace

int runMerge(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(kHelp, stdout);
        return 0;
    }
    const auto outDir = args.option("--out");
    const bool replaceOutput = args.flag("--force");
    const bool asJson = args.flag("--json");
    args.onlyWith("--force", "--out");
    const std::vector<std::string> shareNames = args.positionals();
    args.finish();
    if (!outDir) throw UsageError("--out DIR is required");
    if (shareNames.empty()) throw UsageError("give the share folders to join");
    const std::vector<std::filesystem::path> shares(shareNames.begin(), shareNames.end());

    OutputFolder output = claimOutputFolder(*outDir, replaceOutput);
    auto report = mergeShards(shares, output.staging());
    if (!report) throw CommandFailure(output.userFacing(report.error()));
    if (auto committed = output.commit(); !committed)
        throw CommandFailure(withContext(committed.error(), "--out"));

    if (asJson) std::printf("%s\n", report->dump(2).c_str());
    const std::string summary = (*report)["summary"].get<std::string>();
    if (!(*report)["met"].get<bool>()) {
        printMessage("request not met: " + summary + "; what was found is written");
        return exitCode(ExitStatus::RequestNotMet);
    }
    if (!asJson)
        std::printf("%s; %zu shares joined into %s\n", summary.c_str(), shares.size(),
                    outDir->c_str());
    return 0;
}

}  // namespace matevo::cli
