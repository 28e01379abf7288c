#pragma once
// A small command-line reader shared by every subcommand. Bad usage and bad input throw
// UsageError, which main() turns into a one-line message and exit status 2.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace matevo::cli {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
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
    // Remaining non-option arguments, in order; call after every option was consumed.
    std::vector<std::string> positionals();
    // Throws if anything was left unconsumed (an unknown option, say).
    void finish() const;

private:
    std::string command_;
    std::vector<std::string> args_;
    std::vector<bool> used_;
};

// Parse helpers that throw UsageError naming what was being parsed.
long long parseInteger(const std::string& text, const std::string& what, long long min,
                       long long max);
double parseNumber(const std::string& text, const std::string& what);
std::vector<double> parseNumberList(const std::string& text, const std::string& what);

struct ImageSize {
    int width = 0;
    int height = 0;
};
// "WxH", each side in [minimum, maximum]; `what` names the option ("edit: --size").
ImageSize parseImageSize(const std::string& text, const std::string& what, ImageSize minimum,
                         int maximum);

}  // namespace matevo::cli
