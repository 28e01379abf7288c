#include "gpu/LoaderEnvironment.h"

#include <cstdlib>
#include <sstream>
#include <vector>

#include "common/WorkerThreads.h"

namespace matevo::gpu {

std::optional<std::string> hiddenSystemDriverFolders(const char* current) {
    if (!current) return std::nullopt;
    std::vector<std::string> folders;
    std::istringstream in{std::string(current)};
    for (std::string folder; std::getline(in, folder, ':');)
        if (!folder.empty()) folders.push_back(folder);
    std::string hidden;
    for (const char* system : {"/usr/local/share", "/usr/share"}) {
        bool present = false;
        for (const std::string& folder : folders)
            present = present || folder == system || folder == std::string(system).append("/");
        if (present) continue;
        if (!hidden.empty()) hidden += ':';
        hidden += system;
        hidden += "/vulkan/icd.d";
    }
    if (hidden.empty()) return std::nullopt;
    return hidden;
}

void prepareVulkanEnvironment() {
    if (!std::getenv("VK_DRIVER_FILES") && !std::getenv("VK_ICD_FILENAMES"))
        if (auto hidden = hiddenSystemDriverFolders(std::getenv("XDG_DATA_DIRS"))) {
            std::string added = *hidden;
            if (const char* already = std::getenv("VK_ADD_DRIVER_FILES"); already && *already)
                added = std::string(already).append(":").append(added);
            ::setenv("VK_ADD_DRIVER_FILES", added.c_str(), 1);
        }
    if (!std::getenv("LP_NUM_THREADS"))
        ::setenv("LP_NUM_THREADS", std::to_string(workerThreadCount()).c_str(), 1);
}

}  // namespace matevo::gpu
