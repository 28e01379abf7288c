// The editor's tile cache keeps its renderer's textures and pipelines while only the target
// changes (every step of a dragged target slider), and still draws what a fresh renderer draws
// for the new target.
#include "CandidateRenderCache.h"

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../gpu/GpuTestContext.h"
#include "documents/PresetTextures.h"
#include "evolve/GenomeSampling.h"
#include "gpu/ComputeKernel.h"
#include "gpu/GpuPopulationRenderer.h"
#include "material/FgdTableCache.h"

namespace matevo::editor {
namespace {

namespace fs = std::filesystem;

constexpr int kTileSize = 32;

TEST(CandidateRenderCache, TargetChangeKeepsTexturesAndPipelines) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    // A copy of the textured preset, whose texture is deleted once the cache has read it: a
    // cache that read it again would fail.
    const fs::path source = fs::path(MATEVO_SOURCE_DIR) / "presets";
    const fs::path folder =
        fs::temp_directory_path() / ("matevo_render_cache_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder / "textures");
    const fs::path presetFile = folder / "preset.json";
    fs::copy_file(source / "validation_painted_metal.json", presetFile);
    fs::copy_file(source / "textures" / "paint_roughness.png",
                  folder / "textures" / "paint_roughness.png");
    auto loaded = loadPreset(presetFile);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const Preset preset = loaded->preset;
    auto textures = loadSceneTextures(preset, presetFile);
    ASSERT_TRUE(textures.ok()) << textures.error().message;
    Random random(5);
    std::vector<Genome> candidates;
    for (int i = 0; i < 3; ++i) candidates.push_back(randomGenome(preset.family, random));

    CandidateRenderCache cache(kTileSize, kTileSize, 16, context->device,
                               gpu::RendererRequest(RenderBackend::Gpu));
    ASSERT_TRUE(cache.prepare(preset, presetFile).ok());
    ASSERT_TRUE(cache.tiles(candidates).ok());
    fs::remove_all(folder);
    const std::uint64_t pipelines = gpu::ComputeKernel::pipelinesCreated();

    Preset moved = preset;
    moved.target = randomGenome(preset.family, random);
    const Status prepared = cache.prepare(moved, presetFile);
    ASSERT_TRUE(prepared.ok()) << "the textures were read again: " << prepared.error().message;
    auto tiles = cache.tiles(candidates);
    ASSERT_TRUE(tiles.ok()) << tiles.error().message;
    EXPECT_EQ(gpu::ComputeKernel::pipelinesCreated(), pipelines)
        << "a change of the target built pipelines";

    auto fresh = gpu::GpuPopulationRenderer::create(context->device, defaultFgdTables(), *textures);
    ASSERT_TRUE(fresh.ok()) << fresh.error().message;
    std::vector<MaterialInstance> materials;
    for (const Genome& genome : candidates)
        materials.push_back({genome, preset.family, preset.baseKappa});
    auto expected = (*fresh)->evaluate({moved.target, preset.family, preset.baseKappa}, materials,
                                       preset.scene, kTileSize);
    ASSERT_TRUE(expected.ok()) << expected.error().message;
    ASSERT_NE(cache.targetPicture(), nullptr);
    EXPECT_EQ(cache.targetPicture()->rgba, expected->target.rgba);
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        EXPECT_EQ((*tiles)[i].picture->rgba, expected->candidates[i].rgba) << i;
        EXPECT_EQ((*tiles)[i].deltaE->values, expected->errors.at(ImageMetric::DeltaE00)[i].values)
            << i;
    }
    test::expectNoValidationMessages(*context);
}

}  // namespace
}  // namespace matevo::editor
