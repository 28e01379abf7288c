// The editor's Scene window: the worker renders on the window's device into a DisplayTile that
// the window samples as it is (no read-back, no host upload), and that tile holds the same
// picture `matevo scene` reads back from the renderer's display pass.
#include "SceneViewWorker.h"

#include <chrono>
#include <cstring>
#include <thread>

#include <gtest/gtest.h>

#include "../gpu/GpuTestContext.h"
#include "documents/PresetTextures.h"
#include "gpu/Buffer.h"
#include "gpu/GpuSceneRenderer.h"
#include "material/FgdTableCache.h"
#include "mesh/MeshFile.h"
#include "scene/LightingChoice.h"

namespace matevo::editor {
namespace {

const char* const kPresetFile = MATEVO_SOURCE_DIR "/presets/validation_metal.json";

// Copies a tile's render (SHADER_READ_ONLY_OPTIMAL, RGBA32F) back to the host, for the test
// only; the layout is restored, as the window expects it.
Image readTile(const gpu::Device& device, const gpu::DisplayTile& tile) {
    auto runner = gpu::CommandRunner::create(device);
    EXPECT_TRUE(runner.ok());
    Image image(tile.width, tile.height);
    auto buffer = gpu::Buffer::create(device, image.rgba.size() * sizeof(float),
                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback);
    EXPECT_TRUE(buffer.ok());
    auto commands = runner->begin();
    EXPECT_TRUE(commands.ok());
    if (!runner || !buffer || !commands) return image;
    const VkImage handle = tile.render.handle();
    gpu::transitionImage(*commands, handle, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {uint32_t(tile.width), uint32_t(tile.height), 1};
    vkCmdCopyImageToBuffer(*commands, handle, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           buffer->handle(), 1, &region);
    gpu::transitionImage(*commands, handle, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         0, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    VkMemoryBarrier toHost{};
    toHost.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(*commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                         1, &toHost, 0, nullptr, 0, nullptr);
    EXPECT_TRUE(runner->submitAndWait().ok());
    std::memcpy(image.rgba.data(), buffer->bytes().data(), image.rgba.size() * sizeof(float));
    return image;
}

TEST(SceneViewWorker, TheWindowSamplesTheRenderersDisplayImageOnItsOwnDevice) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto loaded = loadPreset(kPresetFile);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    SceneViewJob job{{}, loaded->preset, kPresetFile, {}};
    job.controls.mesh = 0;      // sphere
    job.controls.instances = 4;
    job.controls.lighting = 2;  // studio
    job.controls.exposure = 0.5f;
    job.controls.width = 96;
    job.controls.height = 64;
    const Preset& preset = loaded->preset;
    Genome other = preset.target;
    other.values[kAlpha2] = std::min(other.alpha2() * 3.0, 1.0);
    job.materials = {{preset.target, preset.family, preset.baseKappa},
                     {other, preset.family, preset.baseKappa}};

    std::optional<SceneViewResult> result;
    {
        SceneViewWorker worker([] {}, context->device);
        worker.request(job);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (!result && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
            result = worker.takeResult();
        }
    }
    ASSERT_TRUE(result.has_value()) << "no render in 120 s";
    ASSERT_NE(result->tile, nullptr) << result->status;
    EXPECT_EQ(result->tile->width, 96);
    EXPECT_EQ(result->tile->height, 64);
    EXPECT_EQ(result->instances.size(), 4u);

    // The same frame through the renderer's own read-back, as `matevo scene` makes it.
    auto mesh = loadMesh("sphere");
    ASSERT_TRUE(mesh.ok());
    auto textures = loadSceneTextures(preset, kPresetFile);
    ASSERT_TRUE(textures.ok());
    SceneSettings settings = preset.scene;
    ASSERT_TRUE(applyLightingChoice("studio", settings, *textures).ok());
    auto runner = gpu::CommandRunner::create(context->device);
    ASSERT_TRUE(runner.ok());
    auto renderer = gpu::GpuSceneRenderer::create(context->device, *runner, defaultFgdTables(),
                                                  *textures, *mesh);
    ASSERT_TRUE(renderer.ok()) << renderer.error().message;
    ASSERT_TRUE(renderer->setMaterials(job.materials).ok());
    auto expected = renderer->render(
        *runner, {96, 64, result->camera, result->instances}, settings,
        gpu::SceneDisplay{job.controls.exposure, ToneMap::Aces});
    ASSERT_TRUE(expected.ok()) << expected.error().message;

    // Reading the tile on the window's device is valid only if it lives there, in the layout
    // the window samples.
    const Image shown = readTile(context->device, *result->tile);
    ASSERT_EQ(shown.rgba.size(), expected->rgba.size());
    std::size_t differing = 0, lit = 0;
    for (std::size_t i = 0; i < shown.rgba.size(); ++i) {
        if (shown.rgba[i] != expected->rgba[i]) ++differing;
        if (i % 4 != 3 && shown.rgba[i] > 0.05f) ++lit;
    }
    EXPECT_EQ(differing, 0u);
    EXPECT_GT(lit, shown.rgba.size() / 2) << "a lit scene over the studio, not an empty tile";
    test::expectNoValidationMessages(*context);
}

}  // namespace
}  // namespace matevo::editor
