#include "gpu/Buffer.h"

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "GpuTestContext.h"

namespace matevo {
namespace {

// What the GPU reads from `buffer` (TRANSFER_SRC usage): its first `count` words, copied on
// the device into a read-back buffer.
std::vector<uint32_t> readOnTheGpu(const gpu::Device& device, gpu::CommandRunner& runner,
                                   const gpu::Buffer& buffer, std::size_t count) {
    const VkDeviceSize bytes = count * sizeof(uint32_t);
    auto readback = gpu::Buffer::create(device, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                        gpu::MemoryUse::Readback);
    EXPECT_TRUE(readback.ok()) << readback.error().message;
    auto commands = runner.begin();
    EXPECT_TRUE(commands.ok()) << commands.error().message;
    if (!readback || !commands) return {};
    const VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(*commands, buffer.handle(), readback->handle(), 1, &region);
    const VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr,
                                 VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_HOST_READ_BIT};
    vkCmdPipelineBarrier(*commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                         1, &toHost, 0, nullptr, 0, nullptr);
    auto submitted = runner.submitAndWait();
    EXPECT_TRUE(submitted.ok()) << submitted.error().message;
    const auto words = readback->as<const uint32_t>();
    return {words.begin(), words.end()};
}

using BufferFill = test::ValidatedGpuTest;

// Either path leaves the GPU reading exactly the bytes given. Auto writes them from the host
// where upload memory is device-local (lavapipe's one memory type is); Staged always leaves
// the buffer in memory the host does not see, filled by a transfer.
TEST_F(BufferFill, EitherPathHoldsTheBytesForTheGpu) {
    const gpu::Device& device = context->device;
    if (device.isCpu()) {
        EXPECT_TRUE(device.uploadsAreDeviceLocal()) << device.name();
    }
    std::vector<uint32_t> words(1000);
    for (std::size_t i = 0; i < words.size(); ++i) words[i] = uint32_t(i * 2654435761u);
    const VkBufferUsageFlags usage =
        VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    for (gpu::FillPath path : {gpu::FillPath::Auto, gpu::FillPath::Staged}) {
        const bool staged = path == gpu::FillPath::Staged || !device.uploadsAreDeviceLocal();
        auto buffer = gpu::Buffer::createFilled(device, *runner, std::as_bytes(std::span(words)),
                                                usage, path);
        ASSERT_TRUE(buffer.ok()) << buffer.error().message;
        EXPECT_EQ(buffer->size(), words.size() * sizeof(uint32_t));
        EXPECT_EQ(buffer->bytes().empty(), staged) << "staged: " << staged;
        EXPECT_EQ(readOnTheGpu(device, *runner, *buffer, words.size()), words)
            << "staged: " << staged;
    }
}

// No bytes still make a valid (16-byte) buffer on either path, with nothing to copy.
TEST_F(BufferFill, NoBytesMakeASmallBuffer) {
    for (gpu::FillPath path : {gpu::FillPath::Auto, gpu::FillPath::Staged}) {
        auto buffer = gpu::Buffer::createFilled(context->device, *runner, {},
                                                VK_BUFFER_USAGE_INDEX_BUFFER_BIT, path);
        ASSERT_TRUE(buffer.ok()) << buffer.error().message;
        EXPECT_EQ(buffer->size(), 16u);
    }
}

}  // namespace
}  // namespace matevo
