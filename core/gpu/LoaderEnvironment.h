#pragma once
// The environment the Vulkan loader and the lavapipe driver read, set up before the first
// instance (main() calls prepareVulkanEnvironment while the process has one thread).
//
// Drivers: without VK_DRIVER_FILES / VK_ICD_FILENAMES the loader looks for driver manifests in
// vulkan/icd.d under each folder of XDG_DATA_DIRS, and under /usr/local/share:/usr/share only
// when the variable is unset. A module system that sets XDG_DATA_DIRS for its own packages
// (`module load ...` gives XDG_DATA_DIRS=/opt/tools/share) thus hides every driver installed
// by the system, and a run that asked for the GPU fell back to the CPU. The system folders are
// appended when missing, as the XDG specification's defaults.
//
// Threads: lavapipe starts as many rendering threads as the machine has cores unless
// LP_NUM_THREADS says otherwise; it is set to matevo's own count (common/WorkerThreads.h: the
// CPUs this process may use) when the user has not set it.
#include <optional>
#include <string>

namespace matevo::gpu {

// XDG_DATA_DIRS's value `current` (null: unset) with /usr/local/share and /usr/share appended
// where missing; nullopt when nothing needs to change (unset, or both there).
std::optional<std::string> withSystemDataDirs(const char* current);

void prepareVulkanEnvironment();

}  // namespace matevo::gpu
