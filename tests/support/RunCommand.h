#pragma once
// Runs the real matevo executable (or any command) for end-to-end tests and captures what it
// printed and its exit status.
#include <filesystem>
#include <string>

namespace matevo::testing {

struct CommandOutput {
    int exitCode = -1;
    std::string out;  // stdout
    std::string err;  // stderr
};

// `arguments` is appended to the shell command line as written (quote paths yourself).
CommandOutput runCommand(const std::string& commandLine);
CommandOutput runMatevo(const std::string& arguments);  // build/matevo ARGUMENTS
// 'PATH', for a command line (test paths hold no single quote).
std::string shellQuoted(const std::filesystem::path& file);

}  // namespace matevo::testing
