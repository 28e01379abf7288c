#pragma once
// Runs the real matevo executable (or any command) for end-to-end tests and captures what it
// printed and its exit status.
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace matevo::testing {

struct CommandOutput {
    int exitCode = -1;
    std::string out;  // stdout
    std::string err;  // stderr
};

// `arguments` is appended to the shell command line as written (quote paths yourself).
CommandOutput runCommand(const std::string& commandLine);
CommandOutput runMatevo(const std::string& arguments);  // build/matevo ARGUMENTS
// Starts `arguments` (the program's path first) as a child process with stdout and stderr sent
// to /dev/null, for tests that signal it while it runs; returns its process id.
pid_t startProcess(const std::vector<std::string>& arguments);
// Waits for the child to end: its exit status, or 128 + the signal that ended it (as a shell).
int waitForProcess(pid_t pid);

// 'PATH', for a command line (test paths hold no single quote).
std::string shellQuoted(const std::filesystem::path& file);

}  // namespace matevo::testing
