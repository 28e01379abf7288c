#include "gpu/GpuContext.h"

namespace matevo::gpu {

Result<GpuContext> GpuContext::createHeadless(const GpuContextOptions& options) {
    auto instance = InstanceBuilder()
                        .enableValidation(options.validation)
                        .printMessages(options.printMessages)
                        .build();
    if (!instance) return instance.error();
    auto device = DeviceBuilder(*instance).build();
    if (!device) return device.error();
    return GpuContext{std::move(instance).value(), std::move(device).value()};
}

}  // namespace matevo::gpu
