#pragma once
// The command-line reader every subcommand uses. A command asks for its options by name
// (flag, option, ...), then for its positionals, then calls finish(): whatever is left is an
// unknown option (answered with the closest option it asked for) or a stray argument.
// Bad usage and bad input throw UsageError; a failure born elsewhere is thrown as the
// CommandFailure of its Error, kind kept. main() prints either in the one message format
// ("matevo COMMAND: TEXT", Messages.h) and exits with the status of its kind. TEXT does not
// repeat the command.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/Choice.h"
#include "common/Result.h"
#include "common/ShortText.h"
#include "files/OutputFolder.h"
#include "fitness/DeltaEBand.h"

namespace matevo::cli {

// A failure that ends the command, with the kind it was born with (common/Result.h), which
// decides the exit status. The message is kept visible (common/ShortText.h): what() is a C
// string, which a NUL in a quoted value would cut.
struct CommandFailure : std::runtime_error {
    explicit CommandFailure(const Error& error)
        : std::runtime_error(visibleText(error.message)), kind(error.kind) {}
    ErrorKind kind;
};

// Bad usage or input that the command line itself finds: a mistyped option, a bad value.
struct UsageError : CommandFailure {
    explicit UsageError(const std::string& message) : CommandFailure(badInput(message)) {}
};

class CommandLine {
public:
    CommandLine(std::string command, std::vector<std::string> args);

    const std::string& command() const { return command_; }
    bool wantsHelp() const;

    // Consume "--name" (a switch). True when present.
    bool flag(const std::string& name);
    // Consume "--name VALUE" or "--name=VALUE".
    std::optional<std::string> option(const std::string& name);
    std::optional<long long> integerOption(const std::string& name, long long min, long long max);
    std::optional<std::uint64_t> unsignedOption(const std::string& name);
    std::optional<double> numberOption(const std::string& name);

    // True when an option already asked for was on the command line.
    bool given(const std::string& name) const;
    // Options that do nothing in a context are refused: throws "OPTION does nothing without
    // OTHER" when OPTION was given and OTHER was not (ask for both first).
    void onlyWith(const std::string& option, const std::string& other) const;

    // Remaining non-option arguments, in order; call after every option was consumed.
    std::vector<std::string> positionals();
    // Throws if anything was left unconsumed: an unknown option (with "did you mean") or an
    // unexpected argument.
    void finish() const;

private:
    std::string command_;
    std::vector<std::string> args_;
    std::vector<bool> used_;
    std::set<std::string> known_;  // every option the command asked for
    std::set<std::string> given_;  // those that were present
};

// Parse helpers that throw UsageError naming what was being parsed ("--size", "--range").
long long parseInteger(const std::string& text, const std::string& what, long long min,
                       long long max);
double parseNumber(const std::string& text, const std::string& what);
// An amount of memory such as "512M" or "16G" (common/ByteSize.h).
std::uint64_t parseByteSizeOption(const std::string& text, const std::string& what);
std::vector<double> parseNumberList(const std::string& text, const std::string& what);
// "OPTION: unknown WHAT 'TEXT'" and the closest of `names` when one is near (a typo), else
// the list of them in words ("(expected a, b or c)").
std::string unknownChoice(const std::string& option, const std::string& what,
                          const std::string& text, const std::vector<std::string>& names);

// The value `text` names in a choice table (common/Choice.h); a UsageError (unknownChoice)
// otherwise. `what` is the kind of thing chosen: "metric", "format".
template <typename Table>
auto parseChoiceOption(const Table& table, const std::string& text, const std::string& option,
                       const std::string& what) {
    if (auto value = parseChoice(table, text)) return *value;
    throw UsageError(unknownChoice(option, what, text, choiceNames(table)));
}

// "LO,HI": a band of mean ΔE00 (0 <= LO <= HI).
DeltaEBand parseDeltaEBand(const std::string& text, const std::string& what);

// The required `--out FILE.png|FILE.exr` of the commands that write one image; its encoder is
// looked for before the work (OutputNeeds.h).
std::string imageOutputPath(CommandLine& args);

// Claims an output folder before the work starts (files/OutputFolder.h: a folder holding other
// files is refused unless `replace`); a refusal is a UsageError naming --out.
OutputFolder claimOutputFolder(const std::filesystem::path& folder, bool replace);

struct ImageSize {
    int width = 0;
    int height = 0;
};
// "WxH", each side in [minimum, maximum]; `what` names the option ("edit: --size").
ImageSize parseImageSize(const std::string& text, const std::string& what, ImageSize minimum,
                         int maximum);

}  // namespace matevo::cli
