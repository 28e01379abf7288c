#pragma once
// Move-only owners of Vulkan handles. A handle created from a VkDevice (or VkInstance) is
// destroyed with the matching vkDestroy* function when its owner goes out of scope, so objects
// are released in reverse order of declaration without hand-written destructors.
#include <utility>

#include <vulkan/vulkan.h>

namespace matevo::gpu {

template <typename Parent, typename Handle, auto Destroy>
class OwnedHandle {
public:
    OwnedHandle() = default;
    OwnedHandle(Parent parent, Handle handle) : parent_(parent), handle_(handle) {}
    OwnedHandle(OwnedHandle&& other) noexcept
        : parent_(other.parent_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
    OwnedHandle& operator=(OwnedHandle&& other) noexcept {
        if (this != &other) {
            reset();
            parent_ = other.parent_;
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
        }
        return *this;
    }
    OwnedHandle(const OwnedHandle&) = delete;
    OwnedHandle& operator=(const OwnedHandle&) = delete;
    ~OwnedHandle() { reset(); }

    Handle get() const { return handle_; }
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

    void reset() {
        if (handle_ != VK_NULL_HANDLE)
            Destroy(parent_, std::exchange(handle_, VK_NULL_HANDLE), nullptr);
    }

private:
    Parent parent_ = VK_NULL_HANDLE;
    Handle handle_ = VK_NULL_HANDLE;
};

// The instance and device own themselves (no parent).
template <typename Handle, auto Destroy>
class OwnedRoot {
public:
    OwnedRoot() = default;
    explicit OwnedRoot(Handle handle) : handle_(handle) {}
    OwnedRoot(OwnedRoot&& other) noexcept : handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
    OwnedRoot& operator=(OwnedRoot&& other) noexcept {
        if (this != &other) {
            reset();
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
        }
        return *this;
    }
    OwnedRoot(const OwnedRoot&) = delete;
    OwnedRoot& operator=(const OwnedRoot&) = delete;
    ~OwnedRoot() { reset(); }

    Handle get() const { return handle_; }
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

    void reset() {
        if (handle_ != VK_NULL_HANDLE) Destroy(std::exchange(handle_, VK_NULL_HANDLE), nullptr);
    }

private:
    Handle handle_ = VK_NULL_HANDLE;
};

using UniqueInstance = OwnedRoot<VkInstance, vkDestroyInstance>;
using UniqueDevice = OwnedRoot<VkDevice, vkDestroyDevice>;
using UniqueBuffer = OwnedHandle<VkDevice, VkBuffer, vkDestroyBuffer>;
using UniqueBufferView = OwnedHandle<VkDevice, VkBufferView, vkDestroyBufferView>;
using UniqueMemory = OwnedHandle<VkDevice, VkDeviceMemory, vkFreeMemory>;
using UniqueImage = OwnedHandle<VkDevice, VkImage, vkDestroyImage>;
using UniqueImageView = OwnedHandle<VkDevice, VkImageView, vkDestroyImageView>;
using UniqueSampler = OwnedHandle<VkDevice, VkSampler, vkDestroySampler>;
using UniqueShaderModule = OwnedHandle<VkDevice, VkShaderModule, vkDestroyShaderModule>;
using UniqueDescriptorSetLayout =
    OwnedHandle<VkDevice, VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using UniqueDescriptorPool = OwnedHandle<VkDevice, VkDescriptorPool, vkDestroyDescriptorPool>;
using UniquePipelineLayout = OwnedHandle<VkDevice, VkPipelineLayout, vkDestroyPipelineLayout>;
using UniquePipeline = OwnedHandle<VkDevice, VkPipeline, vkDestroyPipeline>;
using UniqueCommandPool = OwnedHandle<VkDevice, VkCommandPool, vkDestroyCommandPool>;
using UniqueFence = OwnedHandle<VkDevice, VkFence, vkDestroyFence>;
using UniqueSemaphore = OwnedHandle<VkDevice, VkSemaphore, vkDestroySemaphore>;
using UniqueRenderPass = OwnedHandle<VkDevice, VkRenderPass, vkDestroyRenderPass>;
using UniqueFramebuffer = OwnedHandle<VkDevice, VkFramebuffer, vkDestroyFramebuffer>;

}  // namespace matevo::gpu
