#include "support/RunCommand.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace matevo::testing {

namespace {

std::string readAndRemove(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    in.close();
    std::filesystem::remove(file);
    return text.str();
}

}  // namespace

CommandOutput runCommand(const std::string& commandLine) {
    static int counter = 0;
    const auto base =
        std::filesystem::temp_directory_path() /
        ("matevo_cmd_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    const auto outFile = base.string() + ".out";
    const auto errFile = base.string() + ".err";
    const std::string full = commandLine + " >'" + outFile + "' 2>'" + errFile + "' </dev/null";
    const int status = std::system(full.c_str());
    CommandOutput output;
    output.exitCode = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
    output.out = readAndRemove(outFile);
    output.err = readAndRemove(errFile);
    return output;
}

pid_t startProcess(const std::vector<std::string>& arguments) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        std::vector<char*> argv;
        for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
        argv.push_back(nullptr);
        std::freopen("/dev/null", "w", stdout);
        std::freopen("/dev/null", "w", stderr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    return pid;
}

int waitForProcess(pid_t pid) {
    int status = 0;
    if (::waitpid(pid, &status, 0) != pid) return -1;
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

CommandOutput runMatevo(const std::string& arguments) {
    return runCommand(std::string("'") + MATEVO_BINARY_DIR + "/matevo' " + arguments);
}

std::string shellQuoted(const std::filesystem::path& file) {
    std::string text = "'";  // built by appending: GCC 12 warns falsely on "'" + std::string
    text += file.string();
    text += '\'';
    return text;
}

}  // namespace matevo::testing
