#pragma once
// The environment the Vulkan loader and the lavapipe driver read, set up before the first
// instance (main() calls prepareVulkanEnvironment while the process has one thread).
//
// Drivers: without VK_DRIVER_FILES / VK_ICD_FILENAMES the loader looks for driver manifests in
// vulkan/icd.d under each folder of XDG_DATA_DIRS, and under /usr/local/share:/usr/share only
// when the variable is unset. A module system that sets XDG_DATA_DIRS for its own packages
// (`module load ...` gives XDG_DATA_DIRS=/opt/tools/share) thus hid every driver installed by
// the system, and a run that asked for the GPU fell back to the CPU. The system's driver folders
// that XDG_DATA_DIRS leaves out are added through VK_ADD_DRIVER_FILES, which the loader reads
// besides; XDG_DATA_DIRS itself stays as it is (matevo looks for its font there too).
//
// Threads: lavapipe starts as many rendering threads as the machine has cores unless
// LP_NUM_THREADS says otherwise; it is set to matevo's own count (common/WorkerThreads.h: the
// CPUs this process may use) when the user has not set it.
#include <optional>
#include <string>

namespace matevo::gpu {

// The system's driver folders (/usr/local/share/vulkan/icd.d, /usr/share/vulkan/icd.d) that an
// XDG_DATA_DIRS of `current` hides, ':'-separated; nullopt when none (unset, or both there).
std::optional<std::string> hiddenSystemDriverFolders(const char* current);

void prepareVulkanEnvironment();

}  // namespace matevo::gpu
