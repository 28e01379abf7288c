#pragma once
// The Vulkan instance, built headless by default (no surface extensions, so no DISPLAY is
// needed). A debug-utils messenger, when the loader offers one, feeds a ValidationLog.
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "common/Result.h"
#include "gpu/ValidationLog.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

class Instance {
public:
    VkInstance handle() const { return instance_.get(); }
    const ValidationLog& validationLog() const { return sink_->log; }
    bool validationEnabled() const { return validationEnabled_; }

private:
    friend class InstanceBuilder;
    friend struct MessengerCallback;
    static void destroyMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger,
                                 const VkAllocationCallbacks* allocator);
    using UniqueMessenger =
        OwnedHandle<VkInstance, VkDebugUtilsMessengerEXT, &Instance::destroyMessenger>;

    struct MessageSink {
        ValidationLog log;
        bool echoToStderr = true;
    };

    // On the heap: the messenger keeps a pointer to it while the Instance moves.
    std::unique_ptr<MessageSink> sink_ = std::make_unique<MessageSink>();
    UniqueInstance instance_;
    UniqueMessenger messenger_;
    bool validationEnabled_ = false;
};

class InstanceBuilder {
public:
    InstanceBuilder& applicationName(std::string name);
    // Extensions a caller needs on top of the headless set, e.g. GLFW's surface extensions.
    InstanceBuilder& requireExtensions(const std::vector<std::string>& extensions);
    // Enables VK_LAYER_KHRONOS_validation with synchronization validation; build() fails if
    // the layer is not installed.
    InstanceBuilder& enableValidation(bool enable = true);
    // Echo errors and warnings to stderr as they arrive (they are counted either way).
    InstanceBuilder& printMessages(bool print = true);

    Result<Instance> build() const;

private:
    std::string applicationName_ = "matevo";
    std::vector<std::string> extensions_;
    bool validation_ = false;
    bool printMessages_ = true;
};

}  // namespace matevo::gpu
