#include "gpu/GpuContext.h"

#include <gtest/gtest.h>

#include "GpuTestContext.h"
#include "gpu/Buffer.h"

namespace matevo {
namespace {

TEST(GpuContext, CreatesHeadlessValidatedDevice) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    EXPECT_TRUE(context->instance.validationEnabled());
    EXPECT_FALSE(context->device.name().empty());
    std::printf("Vulkan device: %s\n", context->device.name().c_str());
    test::expectNoValidationMessages(*context);
}

TEST(GpuContext, ReadbackBufferIsHostVisible) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto buffer = gpu::Buffer::create(context->device, 1024, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                      gpu::MemoryUse::Readback);
    ASSERT_TRUE(buffer.ok()) << buffer.error().message;
    EXPECT_EQ(buffer->bytes().size(), 1024u);
    EXPECT_EQ(buffer->as<float>().size(), 256u);
    test::expectNoValidationMessages(*context);
}

// The messenger must really hear the validation layer, or the clean runs above prove nothing.
TEST(GpuContext, MessengerCountsValidationErrors) {
    auto context = gpu::GpuContext::createHeadless({.validation = true, .printMessages = false});
    ASSERT_TRUE(context.ok()) << context.error().message;
    VkBufferCreateInfo invalid{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                               nullptr,
                               0,
                               0,
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                               VK_SHARING_MODE_EXCLUSIVE,
                               0,
                               nullptr};  // size 0 is invalid
    VkBuffer buffer = VK_NULL_HANDLE;
    vkCreateBuffer(context->device.handle(), &invalid, nullptr, &buffer);
    if (buffer != VK_NULL_HANDLE) vkDestroyBuffer(context->device.handle(), buffer, nullptr);
    EXPECT_GT(context->instance.validationLog().errorCount(), 0);
    EXPECT_FALSE(context->instance.validationLog().messages().empty());
}

}  // namespace
}  // namespace matevo
