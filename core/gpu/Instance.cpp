#include "gpu/Instance.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "gpu/SubnormalsFlushed.h"
#include "gpu/VulkanError.h"

namespace matevo::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// Said when the loader finds no driver, most often because the environment hides the
// manifests (XDG_DATA_DIRS set for something else, a stale VK_DRIVER_FILES).
constexpr const char* kNoDriverHint =
    "; the loader finds drivers through VK_DRIVER_FILES or VK_ICD_FILENAMES, else through "
    "vulkan/icd.d under each of $XDG_DATA_DIRS (default /usr/local/share:/usr/share); "
    "`vulkaninfo --summary` lists what it finds";

bool hasInstanceExtension(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> available(count);
    vkEnumerateInstanceExtensionProperties(nullptr, &count, available.data());
    return std::any_of(available.begin(), available.end(), [&](const auto& extension) {
        return std::strcmp(extension.extensionName, name) == 0;
    });
}

bool hasLayer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> available(count);
    vkEnumerateInstanceLayerProperties(&count, available.data());
    return std::any_of(available.begin(), available.end(),
                       [&](const auto& layer) { return std::strcmp(layer.layerName, name) == 0; });
}

}  // namespace

struct MessengerCallback {
    static VKAPI_ATTR VkBool32 VKAPI_CALL
    onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
              const VkDebugUtilsMessengerCallbackDataEXT* data, void* userData) {
        auto& sink = *static_cast<Instance::MessageSink*>(userData);
        const std::string message = data && data->pMessage ? data->pMessage : "(no message)";
        const bool isError = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        // The loader's own messages are about finding drivers and layers: its warnings (e.g.
        // "VK_INSTANCE_LAYERS added a layer", how tests ask for validation) are not problems
        // with our use of Vulkan, and a missing driver already comes back as an Error that
        // callers report in one line, so neither is echoed.
        const bool fromLoader = data && data->pMessageIdName &&
                                std::strcmp(data->pMessageIdName, "Loader Message") == 0;
        if (fromLoader && !isError) return VK_FALSE;
        if (isError)
            sink.log.addError(message);
        else
            sink.log.addWarning(message);
        if (sink.echoToStderr && !fromLoader)
            std::fprintf(stderr, "vulkan %s: %s\n", isError ? "error" : "warning", message.c_str());
        return VK_FALSE;
    }
};

void Instance::destroyMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger,
                                const VkAllocationCallbacks* allocator) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance, messenger, allocator);
}

InstanceBuilder& InstanceBuilder::applicationName(std::string name) {
    applicationName_ = std::move(name);
    return *this;
}

InstanceBuilder& InstanceBuilder::requireExtensions(const std::vector<std::string>& extensions) {
    extensions_.insert(extensions_.end(), extensions.begin(), extensions.end());
    return *this;
}

InstanceBuilder& InstanceBuilder::enableValidation(bool enable) {
    validation_ = enable;
    return *this;
}

InstanceBuilder& InstanceBuilder::printMessages(bool print) {
    printMessages_ = print;
    return *this;
}

Result<Instance> InstanceBuilder::build() const {
    const SubnormalsFlushed subnormalsFlushed;  // for the driver's threads started from here
    uint32_t loaderVersion = 0;
    if (vkEnumerateInstanceVersion(&loaderVersion) != VK_SUCCESS ||
        loaderVersion < VK_API_VERSION_1_2)
        return environmentError("Vulkan: the loader supports only Vulkan < 1.2");

    std::vector<const char*> extensions;
    for (const auto& name : extensions_) extensions.push_back(name.c_str());
    const bool debugUtils = hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (debugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

    std::vector<const char*> layers;
    if (validation_) {
        if (!hasLayer(kValidationLayer))
            return environmentError(std::string("Vulkan: validation requested but ") +
                                    kValidationLayer +
                                    " is not installed (Debian: vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
    }

    Instance instance;
    instance.sink_->echoToStderr = printMessages_;
    instance.validationEnabled_ = validation_;

    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = &MessengerCallback::onMessage;
    messengerInfo.pUserData = instance.sink_.get();

    const VkValidationFeatureEnableEXT syncValidation =
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT validationFeatures{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    validationFeatures.enabledValidationFeatureCount = 1;
    validationFeatures.pEnabledValidationFeatures = &syncValidation;

    // The messenger in pNext also hears what happens during vkCreate/DestroyInstance.
    const void* next = nullptr;
    if (debugUtils) next = &messengerInfo;
    if (validation_) {
        validationFeatures.pNext = next;
        next = &validationFeatures;
    }

    VkApplicationInfo appInfo{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    appInfo.pApplicationName = applicationName_.c_str();
    appInfo.pEngineName = "matevo";
    appInfo.apiVersion = VK_API_VERSION_1_2;

    VkInstanceCreateInfo createInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    createInfo.pNext = next;
    createInfo.pApplicationInfo = &appInfo;
    createInfo.enabledLayerCount = uint32_t(layers.size());
    createInfo.ppEnabledLayerNames = layers.data();
    createInfo.enabledExtensionCount = uint32_t(extensions.size());
    createInfo.ppEnabledExtensionNames = extensions.data();

    VkInstance handle = VK_NULL_HANDLE;
    if (VkResult result = vkCreateInstance(&createInfo, nullptr, &handle); result != VK_SUCCESS) {
        Error error = vulkanError("creating the instance", result);
        if (result == VK_ERROR_INCOMPATIBLE_DRIVER) error.message += kNoDriverHint;
        return error;
    }
    instance.instance_ = UniqueInstance(handle);

    if (debugUtils) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(handle, "vkCreateDebugUtilsMessengerEXT"));
        VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
        if (!create || create(handle, &messengerInfo, nullptr, &messenger) != VK_SUCCESS)
            return environmentError("Vulkan: creating the debug messenger failed");
        instance.messenger_ = Instance::UniqueMessenger(handle, messenger);
    }
    return instance;
}

}  // namespace matevo::gpu
