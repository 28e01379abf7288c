#include "gpu/Device.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <optional>

#include "gpu/SubnormalsFlushed.h"
#include "gpu/VulkanError.h"

namespace matevo::gpu {
namespace {

std::atomic<int> devicesCreated{0};

int preference(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return 1;
        default:
            return 0;
    }
}

bool supportsExtensions(VkPhysicalDevice device, const std::vector<std::string>& required) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> available(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, available.data());
    return std::all_of(required.begin(), required.end(), [&](const std::string& name) {
        return std::any_of(available.begin(), available.end(),
                           [&](const auto& extension) { return name == extension.extensionName; });
    });
}

std::optional<uint32_t> findQueueFamily(VkPhysicalDevice device, VkSurfaceKHR surface) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (uint32_t index = 0; index < count; ++index) {
        if ((families[index].queueFlags & needed) != needed) continue;
        if (surface != VK_NULL_HANDLE) {
            VkBool32 canPresent = VK_FALSE;
            vkGetPhysicalDeviceSurfaceSupportKHR(device, index, surface, &canPresent);
            if (!canPresent) continue;
        }
        return index;
    }
    return std::nullopt;
}

// 64-bit integers in shaders (the ꟻLIP passes store 64-bit words), and 64-bit atomics on
// storage buffers: the scene's visibility pass keeps depth and triangle of each pixel's
// nearest surface in one 64-bit word (atomicMin).
struct Int64Support {
    bool integers = false;
    bool bufferAtomics = false;
};

Int64Support int64SupportOf(VkPhysicalDevice device) {
    VkPhysicalDeviceVulkan12Features features12{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &features12;
    vkGetPhysicalDeviceFeatures2(device, &features);
    const bool integers = features.features.shaderInt64 == VK_TRUE;
    return {integers, integers && features12.shaderBufferInt64Atomics == VK_TRUE};
}

// The geometryShader feature: the scene's fixed-function visibility pass reads gl_PrimitiveID
// in its fragment shader, which SPIR-V allows only with the Geometry capability.
bool supportsGeometryShader(VkPhysicalDevice device) {
    VkPhysicalDeviceFeatures features;
    vkGetPhysicalDeviceFeatures(device, &features);
    return features.geometryShader == VK_TRUE;
}

}  // namespace

Result<uint32_t> Device::memoryTypeFor(uint32_t typeBits, MemoryUse use) const {
    const VkMemoryPropertyFlags host =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkMemoryPropertyFlags required = 0;
    VkMemoryPropertyFlags preferred = 0;
    switch (use) {
        case MemoryUse::DeviceLocal:
            preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
            break;
        case MemoryUse::Upload:
            required = host;
            break;
        case MemoryUse::Readback:
            required = host;
            preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
            break;
    }
    std::optional<uint32_t> fallback;
    for (uint32_t index = 0; index < memory_.memoryTypeCount; ++index) {
        const VkMemoryPropertyFlags flags = memory_.memoryTypes[index].propertyFlags;
        if (!(typeBits & (1u << index)) || (flags & required) != required) continue;
        if ((flags & preferred) == preferred) return index;
        if (!fallback) fallback = index;
    }
    if (fallback) return *fallback;
    return environmentError("Vulkan: no suitable memory type on " + name_);
}

DeviceBuilder& DeviceBuilder::requireExtensions(const std::vector<std::string>& extensions) {
    extensions_.insert(extensions_.end(), extensions.begin(), extensions.end());
    return *this;
}

DeviceBuilder& DeviceBuilder::requirePresentTo(VkSurfaceKHR surface) {
    surface_ = surface;
    return *this;
}

Result<Device> DeviceBuilder::build() const {
    const SubnormalsFlushed subnormalsFlushed;  // for the driver's threads started from here
    uint32_t count = 0;
    if (VkResult result = vkEnumeratePhysicalDevices(instance_, &count, nullptr);
        result != VK_SUCCESS)
        return vulkanError("listing physical devices", result);
    std::vector<VkPhysicalDevice> candidates(count);
    vkEnumeratePhysicalDevices(instance_, &count, candidates.data());

    Device device;
    int bestPreference = -1;
    for (VkPhysicalDevice candidate : candidates) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(candidate, &properties);
        if (properties.apiVersion < VK_API_VERSION_1_2) continue;
        if (!supportsExtensions(candidate, extensions_)) continue;
        auto family = findQueueFamily(candidate, surface_);
        if (!family || preference(properties.deviceType) <= bestPreference) continue;
        bestPreference = preference(properties.deviceType);
        device.physicalDevice_ = candidate;
        device.queueFamily_ = *family;
        device.name_ = properties.deviceName;
        device.isCpu_ = properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
        device.maxTexelBufferElements_ = properties.limits.maxTexelBufferElements;
    }
    if (device.physicalDevice_ == VK_NULL_HANDLE)
        return environmentError(count == 0
                                    ? "Vulkan: no device found"
                                    : "Vulkan: no device supports Vulkan 1.2 with a graphics and "
                                      "compute queue and the needed extensions");
    vkGetPhysicalDeviceMemoryProperties(device.physicalDevice_, &device.memory_);
    const auto uploadType = device.memoryTypeFor(~0u, MemoryUse::Upload);
    device.uploadsAreDeviceLocal_ =
        uploadType && (device.memory_.memoryTypes[*uploadType].propertyFlags &
                       VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT) != 0;

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = device.queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    std::vector<const char*> extensionNames;
    for (const auto& name : extensions_) extensionNames.push_back(name.c_str());

    const Int64Support int64 = int64SupportOf(device.physicalDevice_);
    device.int64_ = int64.integers;
    device.int64Atomics_ = int64.bufferAtomics;
    VkPhysicalDeviceVulkan12Features features12{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    features12.shaderBufferInt64Atomics = device.int64Atomics_;
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &features12;
    features.features.shaderInt64 = device.int64_;
    device.primitiveIds_ = supportsGeometryShader(device.physicalDevice_);
    features.features.geometryShader = device.primitiveIds_;

    VkDeviceCreateInfo createInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    createInfo.pNext = &features;
    createInfo.queueCreateInfoCount = 1;
    createInfo.pQueueCreateInfos = &queueInfo;
    createInfo.enabledExtensionCount = uint32_t(extensionNames.size());
    createInfo.ppEnabledExtensionNames = extensionNames.data();

    VkDevice handle = VK_NULL_HANDLE;
    if (VkResult result = vkCreateDevice(device.physicalDevice_, &createInfo, nullptr, &handle);
        result != VK_SUCCESS)
        return vulkanError("creating the device on " + device.name_, result);
    device.device_ = UniqueDevice(handle);
    vkGetDeviceQueue(handle, device.queueFamily_, 0, &device.queue_);
    ++devicesCreated;
    return device;
}

int logicalDevicesCreated() { return devicesCreated.load(); }

}  // namespace matevo::gpu
