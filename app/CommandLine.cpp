#include "CommandLine.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "OutputNeeds.h"
#include "Suggestion.h"
#include "common/ByteSize.h"
#include "common/ShortText.h"
#include "image/ImageFile.h"

namespace matevo::cli {

CommandLine::CommandLine(std::string command, std::vector<std::string> args)
    : command_(std::move(command)), args_(std::move(args)), used_(args_.size(), false) {}

bool CommandLine::wantsHelp() const {
    for (const auto& arg : args_)
        if (arg == "--help" || arg == "-h") return true;
    return false;
}

bool CommandLine::flag(const std::string& name) {
    known_.insert(name);
    bool found = false;
    for (std::size_t i = 0; i < args_.size(); ++i) {
        if (!used_[i] && args_[i] == name) {
            used_[i] = true;
            found = true;
        }
    }
    if (found) given_.insert(name);
    return found;
}

std::optional<std::string> CommandLine::option(const std::string& name) {
    known_.insert(name);
    std::optional<std::string> value;
    for (std::size_t i = 0; i < args_.size(); ++i) {
        if (used_[i]) continue;
        if (args_[i] == name) {
            if (i + 1 >= args_.size()) throw UsageError(name + " needs a value");
            used_[i] = used_[i + 1] = true;
            value = args_[i + 1];
            ++i;
        } else if (args_[i].rfind(name + "=", 0) == 0) {
            used_[i] = true;
            value = args_[i].substr(name.size() + 1);
        }
    }
    if (value) given_.insert(name);
    return value;
}

std::optional<long long> CommandLine::integerOption(const std::string& name, long long min,
                                                    long long max) {
    auto text = option(name);
    if (!text) return std::nullopt;
    return parseInteger(*text, name, min, max);
}

std::optional<std::uint64_t> CommandLine::unsignedOption(const std::string& name) {
    auto text = option(name);
    if (!text) return std::nullopt;
    std::uint64_t value = 0;
    auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
    if (ec != std::errc() || end != text->data() + text->size())
        throw UsageError(name + ": expected a non-negative integer, got '" + *text + "'");
    return value;
}

std::optional<double> CommandLine::numberOption(const std::string& name) {
    auto text = option(name);
    if (!text) return std::nullopt;
    return parseNumber(*text, name);
}

bool CommandLine::given(const std::string& name) const { return given_.count(name) != 0; }

void CommandLine::onlyWith(const std::string& option, const std::string& other) const {
    if (given(option) && !given(other)) throw UsageError(option + " does nothing without " + other);
}

std::vector<std::string> CommandLine::positionals() {
    std::vector<std::string> result;
    for (std::size_t i = 0; i < args_.size(); ++i) {
        if (used_[i] || (args_[i].size() > 1 && args_[i][0] == '-')) continue;
        used_[i] = true;
        result.push_back(args_[i]);
    }
    return result;
}

void CommandLine::finish() const {
    const std::string seeHelp = "; see matevo " + command_ + " --help";
    for (std::size_t i = 0; i < args_.size(); ++i) {
        if (used_[i]) continue;
        const std::string& arg = args_[i];
        if (arg.size() > 1 && arg[0] == '-') {
            const std::string name = arg.substr(0, arg.find('='));
            const std::vector<std::string> known(known_.begin(), known_.end());
            throw UsageError("unknown option '" + name + "'" + didYouMean(name, known) + seeHelp);
        }
        throw UsageError("unexpected argument '" + arg + "'" + seeHelp);
    }
}

long long parseInteger(const std::string& text, const std::string& what, long long min,
                       long long max) {
    long long value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size())
        throw UsageError(what + ": expected an integer, got '" + text + "'");
    if (value < min || value > max)
        throw UsageError(what + ": must be in [" + std::to_string(min) + ", " +
                         std::to_string(max) + "], got " + text);
    return value;
}

double parseNumber(const std::string& text, const std::string& what) {
    std::size_t consumed = 0;
    double value = 0.0;
    try {
        value = std::stod(text, &consumed);
    } catch (const std::exception&) {
        consumed = 0;
    }
    if (consumed == 0 || consumed != text.size() || !std::isfinite(value))
        throw UsageError(what + ": expected a finite number, got '" + text + "'");
    return value;
}

std::uint64_t parseByteSizeOption(const std::string& text, const std::string& what) {
    if (const auto bytes = parseByteSize(text)) return *bytes;
    throw UsageError(what + ": expected an amount of memory such as 512M or 16G, got '" +
                     shortText(text) + "'");
}

std::vector<double> parseNumberList(const std::string& text, const std::string& what) {
    std::vector<double> values;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) values.push_back(parseNumber(item, what));
    return values;
}

std::string unknownChoice(const std::string& option, const std::string& what,
                          const std::string& text, const std::vector<std::string>& names) {
    const std::string unknown = option + ": unknown " + what + " '" + shortText(text) + "'";
    if (closestWord(text, names)) return unknown + didYouMean(text, names);
    return unknown + " (expected " + inWords(names) + ")";
}

DeltaEBand parseDeltaEBand(const std::string& text, const std::string& what) {
    const auto values = parseNumberList(text, what);
    if (values.size() != 2)
        throw UsageError(what + ": expected LO,HI (two numbers), got '" + text + "'");
    const DeltaEBand band{values[0], values[1]};
    if (auto problem = validateBand(band)) throw UsageError(what + ": " + *problem);
    return band;
}

std::string imageOutputPath(CommandLine& args) {
    const auto out = args.option("--out");
    if (!out) throw UsageError("--out FILE.png|FILE.exr is required");
    if (!isWritableImageType(*out))
        throw UsageError("--out: " + *out + ": the extension must be .png or .exr");
    requireImageEncoder(*out, "--out");
    return *out;
}

OutputFolder claimOutputFolder(const std::filesystem::path& folder, bool replace) {
    auto claimed = OutputFolder::claim(folder, replace);
    if (!claimed) throw CommandFailure(withContext(claimed.error(), "--out"));
    return std::move(*claimed);
}

ImageSize parseImageSize(const std::string& text, const std::string& what, ImageSize minimum,
                         int maximum) {
    const auto x = text.find('x');
    if (x == std::string::npos) throw UsageError(what + ": expected WxH, got '" + text + "'");
    return {int(parseInteger(text.substr(0, x), what + " width", minimum.width, maximum)),
            int(parseInteger(text.substr(x + 1), what + " height", minimum.height, maximum))};
}

}  // namespace matevo::cli
