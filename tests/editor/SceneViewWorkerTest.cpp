// The editor's Scene window: the worker renders on the window's device into a DisplayTile that
// the window samples as it is (no read-back, no host upload), and that tile holds the same
// picture `matevo scene` reads back from the renderer's display pass.
#include "SceneViewWorker.h"

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include <unistd.h>

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

// A job of two materials on `mesh`, `width` x `height`, under the studio.
SceneViewJob smallJob(const std::string& mesh, int width, int height) {
    auto loaded = loadPreset(kPresetFile);
    EXPECT_TRUE(loaded.ok());
    const Preset& preset = loaded->preset;
    SceneViewJob job;
    job.preset = preset;
    job.presetFile = kPresetFile;
    job.controls.mesh = mesh;
    job.controls.instances = 4;
    job.controls.width = width;
    job.controls.height = height;
    Genome other = preset.target;
    other.values[kAlpha2] = std::min(other.alpha2() * 3.0, 1.0);
    job.materials = {{{preset.target, preset.family, preset.baseKappa}, preset.target, "target"},
                     {{other, preset.family, preset.baseKappa}, other, "rougher"}};
    return job;
}

TEST(SceneViewWorker, TheWindowSamplesTheRenderersDisplayImageOnItsOwnDevice) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    SceneViewJob job = smallJob("sphere", 96, 64);
    setLightingChoice("studio", job.preset.scene);
    job.controls.exposure = 0.5f;
    const Preset& preset = job.preset;

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
    ASSERT_TRUE(renderer
                    ->setMaterials(std::vector<MaterialInstance>{job.materials[0].material,
                                                                 job.materials[1].material})
                    .ok());
    auto expected = renderer->render(*runner, {96, 64, result->camera, result->instances}, settings,
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

// Waits until the worker has nothing queued or running and returns its last result.
std::optional<SceneViewResult> settle(SceneViewWorker& worker) {
    std::optional<SceneViewResult> last;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < deadline) {
        const bool busy = worker.busy();
        if (auto result = worker.takeResult()) last = std::move(result);
        if (!busy && last) return last;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return last;
}

std::size_t litValues(const gpu::Device& device, const gpu::DisplayTile& tile) {
    const Image image = readTile(device, tile);
    std::size_t lit = 0;
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        if (i % 4 != 3 && image.rgba[i] > 0.05f) ++lit;
    return lit;
}

TEST(SceneViewWorker, AMeshFileIsDrawnAndOneThatFailsIsOneLineAndNoPicture) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    const auto dir = std::filesystem::temp_directory_path() /
                     ("matevo_scene_meshes" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    // A tetrahedron, counter-clockwise seen from outside.
    std::ofstream(dir / "tetra.obj") << "v 1 1 1\nv -1 -1 1\nv -1 1 -1\nv 1 -1 -1\n"
                                        "f 1 2 4\nf 1 3 2\nf 1 4 3\nf 2 3 4\n";
    std::ofstream(dir / "broken.obj") << "v 0 0 0\nf 1 2 7\n";
    {
        SceneViewWorker worker([] {}, context->device);
        // Lit all round (the studio environment), so most of each tetrahedron shows.
        SceneViewJob tetrahedra = smallJob((dir / "tetra.obj").string(), 96, 64);
        setLightingChoice("studio", tetrahedra.preset.scene);
        worker.request(tetrahedra);
        auto drawn = settle(worker);
        ASSERT_TRUE(drawn.has_value());
        ASSERT_NE(drawn->tile, nullptr) << drawn->status;
        EXPECT_FALSE(drawn->meshFailed);
        EXPECT_NE(drawn->status.find("tetra.obj (4 triangles each)"), std::string::npos)
            << drawn->status;
        EXPECT_GT(litValues(context->device, *drawn->tile), 96u * 64u / 4u) << "tetrahedra drawn";
        EXPECT_EQ(drawn->materials.size(), 2u) << "what the instances' indexes name";

        for (const std::string& bad :
             {(dir / "missing.obj").string(), (dir / "broken.obj").string()}) {
            worker.request(smallJob(bad, 96, 64));
            auto failed = settle(worker);
            ASSERT_TRUE(failed.has_value());
            EXPECT_TRUE(failed->meshFailed) << failed->status;
            EXPECT_EQ(failed->tile, nullptr);
            EXPECT_NE(failed->status.find(std::filesystem::path(bad).filename().string()),
                      std::string::npos)
                << failed->status;
            EXPECT_EQ(failed->status.find('\n'), std::string::npos) << "one line";
        }
        // The scene it had is still there for the next request.
        SceneViewJob again = tetrahedra;
        again.controls.yawDegrees = 30.0f;
        worker.request(again);
        auto redrawn = settle(worker);
        ASSERT_TRUE(redrawn.has_value());
        EXPECT_NE(redrawn->tile, nullptr) << redrawn->status;
    }
    std::filesystem::remove_all(dir);
    test::expectNoValidationMessages(*context);
}

TEST(SceneViewWorker, PreviewsHaveFewerPixelsAndTheNewestRequestWins) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    SceneViewWorker worker([] {}, context->device);
    SceneViewJob preview = smallJob("sphere", 128, 96);
    preview.previewDivisor = 4;
    worker.request(preview);
    auto small = settle(worker);
    ASSERT_TRUE(small.has_value());
    ASSERT_NE(small->tile, nullptr) << small->status;
    EXPECT_TRUE(small->preview);
    EXPECT_EQ(small->tile->width, 32);
    EXPECT_EQ(small->tile->height, 24);
    EXPECT_GT(litValues(context->device, *small->tile), 0u);

    // Three requests at once: whatever was drawn in between, the last picture is the last
    // request's, whole.
    for (const float yaw : {10.0f, 20.0f}) {
        preview.controls.yawDegrees = yaw;
        worker.request(preview);
    }
    SceneViewJob whole = smallJob("sphere", 128, 96);
    whole.controls.yawDegrees = 30.0f;
    worker.request(whole);
    auto last = settle(worker);
    ASSERT_TRUE(last.has_value());
    ASSERT_NE(last->tile, nullptr) << last->status;
    EXPECT_EQ(last->controls, whole.controls);
    EXPECT_FALSE(last->preview);
    EXPECT_EQ(last->tile->width, 128);
    EXPECT_FALSE(worker.busy());
    test::expectNoValidationMessages(*context);
}

}  // namespace
}  // namespace matevo::editor
