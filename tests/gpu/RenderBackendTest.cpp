// The real executable: `matevo render` uses the GPU by default and falls back to the CPU, saying
// so in one line, when no Vulkan device is usable.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "color/ImageDifference.h"
#include "image/ImageFile.h"
#include "support/RunCommand.h"

namespace matevo {
namespace {

std::filesystem::path scratchFile(const std::string& name) {
    return std::filesystem::temp_directory_path() /
           ("matevo_gpu_" + std::to_string(::getpid()) + "_" + name);
}

Image readBack(const std::filesystem::path& file) {
    auto image = readImage(file);
    EXPECT_TRUE(image.ok()) << file << ": " << image.error().message;
    std::filesystem::remove(file);
    return image.ok() ? std::move(image).value() : Image{};
}

TEST(RenderBackend, FallsBackToCpuWithoutVulkanDevice) {
    const auto fallback = scratchFile("fallback.exr");
    const auto reference = scratchFile("cpu.exr");
    const auto result =
        testing::runCommand("VK_DRIVER_FILES=/nonexistent/matevo_icd.json '" MATEVO_BINARY_DIR
                            "/matevo' render --size 40 --out '" +
                            fallback.string() + "'");
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_NE(result.err.find("no usable Vulkan device"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("rendering on the CPU"), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;

    const auto cpu =
        testing::runMatevo("render --backend cpu --size 40 --out '" + reference.string() + "'");
    ASSERT_EQ(cpu.exitCode, 0) << cpu.err;
    const Image fallbackImage = readBack(fallback);
    const Image cpuImage = readBack(reference);
    EXPECT_EQ(fallbackImage.rgba, cpuImage.rgba) << "the fallback is the CPU reference renderer";
}

// When the loader finds no driver, the one-line notice says where the loader looks and how to
// list what it finds.
TEST(RenderBackend, TheNoDriverNoticeSaysWhereTheLoaderLooks) {
    const auto out = scratchFile("no_driver.png");
    const auto result = testing::runCommand(
        "env -u VK_ICD_FILENAMES VK_DRIVER_FILES=/nonexistent/matevo_icd.json '" MATEVO_BINARY_DIR
        "/matevo' render --size 24 --out '" +
        out.string() + "'");
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    for (const char* part :
         {"no compatible Vulkan driver", "VK_DRIVER_FILES", "VK_ICD_FILENAMES", "$XDG_DATA_DIRS",
          "vulkaninfo --summary", "rendering on the CPU instead"})
        EXPECT_NE(result.err.find(part), std::string::npos) << part << "\n" << result.err;
    std::filesystem::remove(out);
}

// XDG_DATA_DIRS set for other packages (as a module system does) hid the system's driver
// manifests from the loader, and the run fell back to the CPU: matevo adds the system folders
// (gpu/LoaderEnvironment.h), so the GPU is found.
TEST(RenderBackend, AModuleSystemsXdgDataDirsDoesNotHideTheDriver) {
    const auto out = scratchFile("module_system.png");
    const auto result = testing::runCommand(
        "env -u VK_DRIVER_FILES -u VK_ICD_FILENAMES XDG_DATA_DIRS=/nonexistent/modules/share "
        "'" MATEVO_BINARY_DIR "/matevo' render --no-fallback --size 24 --out '" +
        out.string() + "'");
    EXPECT_EQ(result.exitCode, 0) << result.err;
    EXPECT_EQ(result.err, "") << "no fallback notice expected";
    std::filesystem::remove(out);
}

// --no-fallback: no usable device is a failure of the machine (exit 1, one line), no CPU render.
TEST(RenderBackend, NoFallbackFailsInsteadOfRenderingOnTheCpu) {
    const auto out = scratchFile("strict.png");
    const auto exported = scratchFile("strict.glb");
    for (const std::string& command :
         {"render --size 24 --out '" + out.string() + "'",
          std::string("variants --count 1 --band 1,10 --size 24 --fitness-size 16 "
                      "--max-evaluations 50"),
          "evolve --population 4 --generations 1 --size 24 --out '" + out.string() + "'",
          "experiment --runs 1 --population 4 --generations 1 --size 24 --metric chebyshev "
          "--out '" +
              out.string() + "'",
          "export --fit-size 16 --fit-renders 20 --report-size 16 --out '" + exported.string() +
              "'"}) {
        const auto result = testing::runCommand(
            "VK_DRIVER_FILES=/nonexistent/matevo_icd.json '" MATEVO_BINARY_DIR "/matevo' " +
            command + " --no-fallback");
        EXPECT_EQ(result.exitCode, 1) << command << "\n" << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_NE(result.err.find("--no-fallback"), std::string::npos) << result.err;
        EXPECT_EQ(result.err.find("rendering on the CPU instead"), std::string::npos) << result.err;
        EXPECT_FALSE(std::filesystem::exists(out));
        EXPECT_FALSE(std::filesystem::exists(exported));
    }
    const auto contradiction =
        testing::runMatevo("render --backend cpu --no-fallback --out '" + out.string() + "'");
    EXPECT_EQ(contradiction.exitCode, 2) << contradiction.err;
}

TEST(RenderBackend, GpuIsTheDefaultAndMatchesCpu) {
    const auto gpuFile = scratchFile("gpu.exr");
    const auto cpuFile = scratchFile("cpu_default.exr");
    const auto gpu = testing::runMatevo("render --size 40 --out '" + gpuFile.string() + "'");
    ASSERT_EQ(gpu.exitCode, 0) << gpu.err;
    EXPECT_EQ(gpu.err, "") << "no fallback notice and no validation message expected";
    const auto cpu =
        testing::runMatevo("render --backend cpu --size 40 --out '" + cpuFile.string() + "'");
    ASSERT_EQ(cpu.exitCode, 0) << cpu.err;
    auto difference = compareImages(readBack(gpuFile), readBack(cpuFile));
    ASSERT_TRUE(difference.ok()) << difference.error().message;
    EXPECT_GT(difference->stats.pixels, 0u);
    EXPECT_LT(difference->stats.mean, 0.5);
}

// Every rendering command takes --backend: with no Vulkan device, gpu falls back with exactly
// one notice and cpu never tries the GPU (so it says nothing).
TEST(RenderBackend, EveryCommandHonoursTheBackendOption) {
    const auto out =
        std::filesystem::temp_directory_path() / ("matevo_backend_" + std::to_string(::getpid()));
    std::filesystem::create_directories(out);
    const std::string commands[] = {
        "render --size 24 --out '" + (out / "render.png").string() + "'",
        // --force: each command runs twice into its folder (gpu, then cpu).
        "evolve --population 4 --generations 1 --size 24 --force --out '" +
            (out / "evolve").string() + "'",
        "experiment --runs 1 --population 4 --generations 1 --size 24 --metric chebyshev "
        "--force --out '" +
            (out / "experiment").string() + "'",
    };
    for (const std::string& command : commands) {
        for (const char* backend : {"gpu", "cpu"}) {
            const auto result = testing::runCommand(
                "VK_DRIVER_FILES=/nonexistent/matevo_icd.json '" MATEVO_BINARY_DIR "/matevo' " +
                command + " --backend " + backend);
            ASSERT_EQ(result.exitCode, 0) << command << "\n" << result.err;
            std::size_t notices = 0;
            for (std::size_t at = result.err.find("no usable Vulkan device");
                 at != std::string::npos; at = result.err.find("no usable Vulkan device", at + 1))
                ++notices;
            EXPECT_EQ(notices, backend == std::string("gpu") ? 1u : 0u)
                << command << " --backend " << backend << "\n"
                << result.err;
        }
    }
    std::filesystem::remove_all(out);
}

TEST(RenderBackend, RejectsUnknownBackend) {
    for (const char* command :
         {"render --out x.png", "evolve --out x", "experiment --out x", "edit"}) {
        const auto result = testing::runMatevo(std::string(command) + " --backend opengl");
        EXPECT_EQ(result.exitCode, 2) << command;
        EXPECT_NE(result.err.find("--backend"), std::string::npos) << command << result.err;
    }
}

}  // namespace
}  // namespace matevo
