// Exports that meet at one file (files/CompanionFiles.h), through the real executable: several
// `matevo export` processes writing one .gltf or .mtlx at once, and an export through a symlink.
// Afterwards the main file must be one export's whole result and every file it names must be
// there, holding what that export wrote.
#include <filesystem>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include "support/FileContents.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;
using testing::contentsOf;
using testing::shellQuoted;

// Two materials whose companions differ: a roughness texture, and a base-colour texture.
const std::vector<std::string> kPresets = {"validation_painted_metal", "validation_metal_depth"};

std::string exportCommand(const std::string& preset, const fs::path& out) {
    return "'" MATEVO_BINARY_DIR "/matevo' export --preset " + preset + " --out " +
           shellQuoted(out) + " --backend cpu --fit-size 16 --fit-renders 30 --report-size 16";
}

// The files a .gltf or .mtlx names, relative to its folder.
std::vector<std::string> referencedFiles(const fs::path& mainFile) {
    const std::string text = contentsOf(mainFile);
    std::vector<std::string> names;
    if (mainFile.extension() == ".gltf") {
        const auto json = nlohmann::json::parse(text);
        for (const char* kind : {"buffers", "images"})
            for (const auto& entry : json.value(kind, nlohmann::json::array()))
                if (entry.contains("uri")) names.push_back(entry["uri"]);
    } else {
        const std::regex file("type=\"filename\" value=\"([^\"]+)\"");
        for (std::sregex_iterator match(text.begin(), text.end(), file), end; match != end; ++match)
            names.push_back((*match)[1]);
    }
    return names;
}

// `mainFile` is byte for byte one of `solos` (the same export made alone, in its own folder),
// and every file it names is there with the bytes that export wrote.
void expectWholeExport(const fs::path& mainFile, const std::vector<fs::path>& solos) {
    const std::string written = contentsOf(mainFile);
    const fs::path* solo = nullptr;
    for (const auto& candidate : solos)
        if (contentsOf(candidate) == written) solo = &candidate;
    ASSERT_NE(solo, nullptr) << mainFile << " is none of the exports' results";
    const auto names = referencedFiles(mainFile);
    EXPECT_FALSE(names.empty());
    for (const auto& name : names) {
        ASSERT_TRUE(fs::exists(mainFile.parent_path() / name)) << name << " is missing";
        EXPECT_EQ(contentsOf(mainFile.parent_path() / name), contentsOf(solo->parent_path() / name))
            << name;
    }
    if (mainFile.extension() == ".gltf") {
        tinygltf::TinyGLTF loader;
        tinygltf::Model model;
        std::string error, warning;
        EXPECT_TRUE(loader.LoadASCIIFromFile(&model, &error, &warning, mainFile.string())) << error;
    }
}

// Each material exported alone to FOLDER/PRESET/NAME: what a whole export of it is.
std::vector<fs::path> exportsAlone(const testing::ScratchFolder& folder, const std::string& name) {
    std::vector<fs::path> solos;
    for (const auto& preset : kPresets) {
        fs::create_directories(folder / preset);
        solos.push_back(folder / preset / name);
        EXPECT_EQ(testing::runCommand(exportCommand(preset, solos.back())).exitCode, 0);
    }
    return solos;
}

class ConcurrentExport : public ::testing::TestWithParam<std::string> {};

TEST_P(ConcurrentExport, ParallelExportsToOneFileLeaveOneWholeResult) {
    testing::ScratchFolder folder("concurrent_export");
    const std::string name = "out." + GetParam();
    const std::vector<fs::path> solos = exportsAlone(folder, name);
    ASSERT_NE(contentsOf(solos[0]), contentsOf(solos[1]));

    const fs::path shared = folder / name;
    for (int round = 0; round < 2; ++round) {
        std::string parallel;
        for (int writer = 0; writer < 4; ++writer) {
            parallel += '(';  // appended piecewise: GCC 12 warns falsely (-Wrestrict)
            parallel += exportCommand(kPresets[writer % 2], shared);
            parallel += " >/dev/null || echo failed) & ";
        }
        const auto run = testing::runCommand(parallel + "wait");
        EXPECT_EQ(run.out, "") << run.err;  // every export succeeded
        expectWholeExport(shared, solos);
    }
}

TEST_P(ConcurrentExport, AnExportThroughASymlinkWritesBesideTheFileItLeadsTo) {
    testing::ScratchFolder folder("symlink_export");
    const std::string name = "out." + GetParam();
    const std::vector<fs::path> solos = exportsAlone(folder, name);
    fs::create_directories(folder / "assets");
    fs::create_directories(folder / "links");
    const fs::path real = folder / "assets" / name, link = folder / "links" / name;
    fs::create_symlink(fs::path("..") / "assets" / name, link);
    for (const auto& preset : kPresets) {
        ASSERT_EQ(testing::runCommand(exportCommand(preset, link)).exitCode, 0);
        EXPECT_TRUE(fs::is_symlink(link));
        expectWholeExport(real, solos);
    }
    // The replaced export's companions are gone; none were put beside the link.
    EXPECT_EQ(std::distance(fs::directory_iterator(folder / "assets"), {}),
              std::ptrdiff_t(1 + referencedFiles(real).size()));
    EXPECT_EQ(std::distance(fs::directory_iterator(folder / "links"), {}), 1);
}

INSTANTIATE_TEST_SUITE_P(Formats, ConcurrentExport, ::testing::Values("gltf", "mtlx"));

}  // namespace
}  // namespace matevo
