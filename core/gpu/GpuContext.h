#pragma once
// The instance and device together, for headless work (CLI, tests, benchmarks). Members are
// declared so that the device is destroyed before the instance.
#include "common/Result.h"
#include "gpu/Device.h"
#include "gpu/Instance.h"

namespace matevo::gpu {

struct GpuContextOptions {
    bool validation = false;    // VK_LAYER_KHRONOS_validation + synchronization validation
    bool printMessages = true;  // echo validation errors and warnings to stderr
};

struct GpuContext {
    Instance instance;
    Device device;

    // An Error here means "no usable Vulkan device": callers fall back to the CPU.
    static Result<GpuContext> createHeadless(const GpuContextOptions& options = {});
};

}  // namespace matevo::gpu
