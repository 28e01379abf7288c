// A creation that fails half-way must leave no Vulkan object behind. The validation layer's
// object tracker reports every object still alive when a device is destroyed, so each test
// destroys its own device and then reads what the layer said.
#include <string>

#include <gtest/gtest.h>

#include "gpu/GpuContext.h"
#include "gpu/GpuImage.h"

namespace matevo {
namespace {

gpu::GpuContext quietValidatedContext() {
    auto context = gpu::GpuContext::createHeadless({.validation = true, .printMessages = false});
    EXPECT_TRUE(context.ok()) << (context.ok() ? "" : context.error().message);
    return std::move(context).value();
}

void destroyDevice(gpu::GpuContext& context) { gpu::Device dying = std::move(context.device); }

std::string allMessages(const gpu::GpuContext& context) {
    std::string joined;
    for (const std::string& message : context.instance.validationLog().messages())
        joined += message + "\n";
    return joined;
}

// The check below proves nothing unless a leaked object is really reported.
TEST(GpuLifetime, ValidationReportsAnImageLeftAlive) {
    gpu::GpuContext context = quietValidatedContext();
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = VK_FORMAT_R8G8B8A8_UNORM;
    info.extent = {4, 4, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    VkImage leaked = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateImage(context.device.handle(), &info, nullptr, &leaked), VK_SUCCESS);
    ASSERT_EQ(context.instance.validationLog().errorCount(), 0) << allMessages(context);
    destroyDevice(context);
    EXPECT_GT(context.instance.validationLog().errorCount(), 0);
    EXPECT_NE(allMessages(context).find("VkImage"), std::string::npos) << allMessages(context);
}

// The image is created, its memory cannot be: GpuImage must destroy the image it made. The
// layer objects to the oversized request itself (heard before the device goes); destroying the
// device must then add nothing, which it would for a leaked image or memory.
TEST(GpuLifetime, FailedImageCreationLeavesNoObjectBehind) {
    gpu::GpuContext context = quietValidatedContext();
    gpu::GpuImageSpec huge;
    huge.type = VK_IMAGE_TYPE_3D;
    huge.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    huge.extent = {2048, 2048, 2048};  // 128 GiB: more than any heap
    auto image = gpu::GpuImage::create(context.device, huge);
    ASSERT_FALSE(image.ok());
    EXPECT_NE(image.error().message.find("bytes of image memory"), std::string::npos)
        << image.error().message;
    const gpu::ValidationLog& log = context.instance.validationLog();
    const int errorsBefore = log.errorCount();
    const int warningsBefore = log.warningCount();
    destroyDevice(context);
    EXPECT_EQ(log.errorCount(), errorsBefore) << allMessages(context);
    EXPECT_EQ(log.warningCount(), warningsBefore) << allMessages(context);
}

}  // namespace
}  // namespace matevo
