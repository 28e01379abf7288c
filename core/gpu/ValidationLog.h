#pragma once
// What the VK_EXT_debug_utils messenger heard: counts of errors and warnings (from the
// validation layer when it is enabled, from the loader otherwise) and the first few messages,
// so tests can fail on any and say why.
#include <mutex>
#include <string>
#include <vector>

namespace matevo::gpu {

class ValidationLog {
public:
    void addError(std::string message);
    void addWarning(std::string message);

    int errorCount() const;
    int warningCount() const;
    // The first messages received, each prefixed by "error: " or "warning: ".
    std::vector<std::string> messages() const;

private:
    static constexpr std::size_t kKeptMessages = 20;
    void keep(std::string message);

    mutable std::mutex mutex_;  // drivers may call the messenger from their own threads
    int errors_ = 0;
    int warnings_ = 0;
    std::vector<std::string> messages_;
};

}  // namespace matevo::gpu
