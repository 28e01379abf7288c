#include "gpu/LoaderEnvironment.h"

#include <cstdlib>
#include <sstream>
#include <vector>

#include "common/WorkerThreads.h"

namespace matevo::gpu {

std::optional<std::string> withSystemDataDirs(const char* current) {
    if (!current) return std::nullopt;
    std::vector<std::string> folders;
    std::istringstream in{std::string(current)};
    for (std::string folder; std::getline(in, folder, ':');)
        if (!folder.empty()) folders.push_back(folder);
    std::string value = current;
    bool changed = false;
    for (const char* system : {"/usr/local/share", "/usr/share"}) {
        bool present = false;
        for (const std::string& folder : folders)
            present = present || folder == system || folder == std::string(system).append("/");
        if (present) continue;
        if (!value.empty() && value.back() != ':') value += ':';
        value += system;
        changed = true;
    }
    if (!changed) return std::nullopt;
    return value;
}

void prepareVulkanEnvironment() {
    if (!std::getenv("VK_DRIVER_FILES") && !std::getenv("VK_ICD_FILENAMES"))
        if (auto dataDirs = withSystemDataDirs(std::getenv("XDG_DATA_DIRS")))
            ::setenv("XDG_DATA_DIRS", dataDirs->c_str(), 1);
    if (!std::getenv("LP_NUM_THREADS"))
        ::setenv("LP_NUM_THREADS", std::to_string(workerThreadCount()).c_str(), 1);
}

}  // namespace matevo::gpu
