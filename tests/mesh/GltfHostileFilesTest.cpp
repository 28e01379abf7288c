// glTF files made to crash, hang or inflate the reader: offsets near 2^64, JSON nested 20,000
// deep, nodes sharing children 200 levels deep, and external buffers that are FIFOs, folders,
// huge sparse files or paths out of the glTF's folder. Each is refused with one line naming the
// file. The crafted files are the glTF and GLB fuzz seeds (tests/fuzz/corpus), so the fuzz
// targets replay them too.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/MemoryBudget.h"
#include "files/JsonReader.h"
#include "mesh/GltfReader.h"
#include "mesh/MeshFile.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kCorpus = fs::path(MATEVO_SOURCE_DIR) / "tests/fuzz/corpus";

void expectOneLineNaming(const Result<Mesh>& mesh, const std::string& file,
                         const std::string& problem) {
    ASSERT_FALSE(mesh.ok()) << file;
    const std::string& message = mesh.error().message;
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << file << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(GltfHostileFiles, CraftedSeedsAreRefusedNamingTheProblem) {
    const std::map<std::string, std::string> expected = {
        {"gltf/accessor-offset-near-2-64.gltf", "NORMAL accessor: byte offsets overflow"},
        {"gltf/bufferview-offset-near-2-64.gltf", "POSITION bufferView: byte offsets overflow"},
        {"gltf/bufferview-length-near-2-64.gltf", "POSITION: bufferView reads past the end"},
        {"gltf/accessor-count-near-2-62.gltf", "POSITION accessor: byte sizes overflow"},
        {"gltf/stride-times-count-wraps.gltf", "POSITION accessor: byte sizes overflow"},
        {"gltf/node-cycle.gltf", "node 0 is its own ancestor"},
        {"gltf/extras-nested-20000.gltf", "JSON nested deeper than 256 levels"},
        {"gltf/shared-children-200-levels.gltf", "more than 100000 instances"},
        {"glb/accessor-offset-near-2-64.glb", "NORMAL accessor: byte offsets overflow"},
        {"glb/extras-nested-20000.glb", "JSON nested deeper than 256 levels"},
        {"glb/shared-children-200-levels.glb", "more than 100000 instances"},
        // Found by fuzz_glb: a buffer of byteLength 0 made tinygltf throw out_of_range.
        {"glb/regression-buffer-length-0.glb",
         "not a valid glTF 2.0 file (an index or length out of range)"},
    };
    for (const auto& [name, problem] : expected)
        expectOneLineNaming(loadMesh((kCorpus / name).string()), fs::path(name).filename(),
                            problem);
    // The seeds they were made from load.
    for (const char* name : {"gltf/triangle.gltf", "glb/triangle.glb"}) {
        auto mesh = loadMesh((kCorpus / name).string());
        ASSERT_TRUE(mesh.ok()) << mesh.error().message;
        EXPECT_EQ(mesh->triangleCount(), 1u);
    }
}

TEST(GltfHostileFiles, DeepJsonIsRefusedBeforeAnyParserInEveryReader) {
    const std::string deep = std::string(20000, '[') + std::string(20000, ']');
    const auto nesting = checkJsonNesting(deep, "deep.json");
    ASSERT_FALSE(nesting.ok());
    EXPECT_EQ(nesting.error().message,
              "deep.json: JSON nested deeper than 256 levels (at byte 256)");
    // Brackets inside strings, escaped quotes included, do not count.
    const std::string quoted = "{\"a\": \"\\\"" + std::string(1000, '[') + "\"}";
    EXPECT_TRUE(checkJsonNesting(quoted, "quoted.json").ok());
    const std::string atLimit = std::string(256, '[') + std::string(256, ']');
    EXPECT_TRUE(checkJsonNesting(atLimit, "limit.json").ok());
    std::vector<std::string> warnings;
    const auto read =
        readJsonDocument<int>(deep, "deep.json", warnings, [](const nlohmann::json&) { return 1; });
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().message.find("nested deeper"), std::string::npos);
}

// One triangle whose buffer is the external file `uri`, written into `folder`.
fs::path gltfNaming(const fs::path& folder, const std::string& uri) {
    const json gltf = json::parse((std::ifstream(kCorpus / "gltf/triangle.gltf")));
    json external = gltf;
    external["buffers"][0]["uri"] = uri;
    const fs::path file = folder / "external.gltf";
    std::ofstream(file) << external.dump();
    return file;
}

TEST(GltfHostileFiles, ExternalBuffersOnlyFromInsideTheFolderAndOnlyRegularFiles) {
    testing::ScratchFolder scratch("gltf_external");
    const fs::path folder = scratch / "model";
    fs::create_directories(folder / "data");
    fs::create_directories(folder / "data.bin");
    ASSERT_EQ(::mkfifo((folder / "fifo.bin").c_str(), 0600), 0);
    std::ofstream(scratch / "outside.bin") << std::string(80, 'x');
    fs::create_symlink(scratch / "outside.bin", folder / "link.bin");
    // A 3 GiB file that takes no disk: only its size may be looked at.
    {
        std::ofstream(folder / "sparse.bin").close();
        fs::resize_file(folder / "sparse.bin", 3ull << 30);
    }
    const std::map<std::string, std::string> refused = {
        {"fifo.bin", "it is a pipe (FIFO)"},
        {"data.bin", "it is a folder"},
        {"../outside.bin", "steps out of the glTF file's folder"},
        {"data/../../outside.bin", "steps out of the glTF file's folder"},
        {(scratch / "outside.bin").string(), "an absolute path"},
        {"link.bin", "a symlink that leads out"},
        {"sparse.bin", "more than the limit"},
        {"absent.bin", "no such file"},
    };
    for (const auto& [uri, problem] : refused) {
        const auto mesh = loadMesh(gltfNaming(folder, uri).string());
        expectOneLineNaming(mesh, "external.gltf", problem);
        if (!mesh.ok()) {
            EXPECT_NE(mesh.error().message.find(uri), std::string::npos) << uri;
        }
    }
    // A buffer in a subfolder is inside: the seed's triangle, its data URI's bytes in a file.
    const float corners[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    const std::uint16_t order[4] = {0, 1, 2, 0};
    std::ofstream bin(folder / "data/triangle.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(corners), sizeof corners);
    bin.write(reinterpret_cast<const char*>(order), sizeof order);
    bin.close();
    const auto inside = loadMesh(gltfNaming(folder, "data/triangle.bin").string());
    ASSERT_TRUE(inside.ok()) << inside.error().message;
    EXPECT_EQ(inside->triangleCount(), 1u);

    // Images are not needed: one that is refused (here a FIFO) costs nothing, not even a wait.
    json withImage = json::parse((std::ifstream(kCorpus / "gltf/triangle.gltf")));
    withImage["images"] = json::array({{{"uri", "fifo.bin"}}});
    std::ofstream(folder / "image.gltf") << withImage.dump();
    const auto imaged = loadMesh((folder / "image.gltf").string());
    ASSERT_TRUE(imaged.ok()) << imaged.error().message;

    // The size is checked against the memory limit too, before reading.
    setMemoryLimitBytes(100);
    const auto overBudget = loadMesh(gltfNaming(folder, "data/triangle.bin").string());
    setMemoryLimitBytes(0);
    expectOneLineNaming(overBudget, "external.gltf", "more than the limit");
}

}  // namespace
}  // namespace matevo
