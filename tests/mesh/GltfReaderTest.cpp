#include "mesh/GltfReader.h"

#include <cstring>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "mesh/MeshFile.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

using nlohmann::json;

// One triangle in the z = 0 plane facing +z: float positions, float normals, uint16 indices,
// in an external .bin file.
std::vector<unsigned char> triangleBuffer() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const float normals[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    const std::uint16_t indices[4] = {0, 1, 2, 0};  // padded to 4 bytes
    std::vector<unsigned char> bytes(sizeof positions + sizeof normals + sizeof indices);
    std::memcpy(bytes.data(), positions, sizeof positions);
    std::memcpy(bytes.data() + 36, normals, sizeof normals);
    std::memcpy(bytes.data() + 72, indices, sizeof indices);
    return bytes;
}

json triangleGltf() {
    return json{
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", json::array({{{"nodes", {0}}}})},
        // A parent node that doubles the size and a child that moves the triangle along x.
        {"nodes", json::array({{{"scale", {2.0, 2.0, 2.0}}, {"children", {1}}},
                               {{"translation", {3.0, 0.0, 0.0}}, {"mesh", 0}}})},
        {"meshes", json::array({{{"primitives",
                                  json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}},
                                                {"indices", 2}}})}}})},
        {"buffers", json::array({{{"uri", "triangle.bin"}, {"byteLength", 80}}})},
        {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 72}},
                                     {{"buffer", 0}, {"byteOffset", 72}, {"byteLength", 6}}})},
        {"accessors",
         json::array(
             {{{"bufferView", 0},
               {"componentType", 5126},
               {"count", 3},
               {"type", "VEC3"},
               {"min", {0, 0, 0}},
               {"max", {1, 1, 0}}},
              {{"bufferView", 0},
               {"byteOffset", 36},
               {"componentType", 5126},
               {"count", 3},
               {"type", "VEC3"}},
              {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}})}};
}

class GltfFiles : public ::testing::Test {
protected:
    testing::ScratchFolder folder{"gltf"};

    std::filesystem::path write(const std::string& name, const json& gltf) {
        const std::vector<unsigned char> bytes = triangleBuffer();
        std::ofstream(folder / "triangle.bin", std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        std::ofstream(folder / name) << gltf.dump(2);
        return folder / name;
    }
};

TEST_F(GltfFiles, ReadsATrianglePlacedByItsNodes) {
    auto mesh = readGltf(write("triangle.gltf", triangleGltf()));
    ASSERT_TRUE(mesh.ok()) << mesh.error().message;
    ASSERT_EQ(mesh->triangleCount(), 1u);
    // scale 2 after translate 3: x = 2 * (x + 3).
    EXPECT_EQ(mesh->vertices[0].position, glm::vec3(6, 0, 0));
    EXPECT_EQ(mesh->vertices[1].position, glm::vec3(8, 0, 0));
    EXPECT_EQ(mesh->vertices[2].position, glm::vec3(6, 2, 0));
    EXPECT_EQ(mesh->vertices[0].normal, glm::vec3(0, 0, 1));
}

// A matrix that mirrors x turns the winding inside out: the reader swaps two corners so that the
// placed triangle still faces its (mirrored) normal. The same mesh placed a second time, unmoved,
// follows the first in the arrays with its own indices.
TEST_F(GltfFiles, AMirroringMatrixKeepsTheTriangleFacingItsNormal) {
    json gltf = triangleGltf();
    gltf["scenes"][0]["nodes"] = {0, 2};
    gltf["nodes"][0] = {{"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}},
                        {"children", {1}}};
    gltf["nodes"].push_back({{"mesh", 0}});
    auto mesh = readGltf(write("mirrored.gltf", gltf));
    ASSERT_TRUE(mesh.ok()) << mesh.error().message;
    ASSERT_EQ(mesh->triangleCount(), 2u);
    ASSERT_EQ(mesh->vertices.size(), 6u);
    // Mirrored: x = -(x + 3).
    EXPECT_EQ(mesh->vertices[0].position, glm::vec3(-3, 0, 0));
    EXPECT_EQ(mesh->vertices[1].position, glm::vec3(-4, 0, 0));
    EXPECT_EQ(mesh->vertices[3].position, glm::vec3(0, 0, 0));
    for (std::size_t triangle = 0; triangle < 2; ++triangle) {
        const std::uint32_t* corner = &mesh->indices[3 * triangle];
        EXPECT_GE(corner[0], 3 * triangle);
        EXPECT_LT(corner[0], 3 * triangle + 3);
        const glm::vec3 a = mesh->vertices[corner[0]].position,
                        b = mesh->vertices[corner[1]].position,
                        c = mesh->vertices[corner[2]].position;
        const glm::vec3 facing = glm::cross(b - a, c - a);
        EXPECT_GT(glm::dot(facing, mesh->vertices[corner[0]].normal), 0.0f) << triangle;
    }
}

TEST_F(GltfFiles, ReadsTheSameTriangleFromAGlbWrittenByTinygltf) {
    const auto source = write("triangle.gltf", triangleGltf());
    tinygltf::TinyGLTF gltf;
    tinygltf::Model model;
    std::string errors, warnings;
    ASSERT_TRUE(gltf.LoadASCIIFromFile(&model, &errors, &warnings, source.string())) << errors;
    const auto binary = folder / "triangle.glb";
    ASSERT_TRUE(gltf.WriteGltfSceneToFile(&model, binary.string(), true, true, false, true));
    auto fromText = readGltf(source);
    auto fromBinary = loadMesh(binary.string());
    ASSERT_TRUE(fromText.ok() && fromBinary.ok());
    ASSERT_EQ(fromBinary->triangleCount(), 1u);
    // loadMesh fits the mesh into the unit sphere; the triangle keeps its shape.
    const float side =
        glm::length(fromBinary->vertices[1].position - fromBinary->vertices[0].position);
    const float hypotenuse =
        glm::length(fromBinary->vertices[2].position - fromBinary->vertices[1].position);
    EXPECT_NEAR(hypotenuse / side, std::sqrt(2.0f), 1e-5f);
}

TEST_F(GltfFiles, MissingNormalsAreComputed) {
    json gltf = triangleGltf();
    gltf["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
    auto mesh = readGltf(write("triangle.gltf", gltf));
    ASSERT_TRUE(mesh.ok()) << mesh.error().message;
    EXPECT_LT(glm::length(mesh->vertices[0].normal - glm::vec3(0, 0, 1)), 1e-6f);
}

TEST_F(GltfFiles, BrokenFilesGiveOneLineNamingTheFile) {
    std::vector<std::pair<json, std::string>> cases;
    {
        json gltf = triangleGltf();
        gltf["accessors"][0]["count"] = 300;  // past the end of its buffer view
        cases.push_back({gltf, "reads past the end"});
    }
    {
        json gltf = triangleGltf();
        gltf["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
        cases.push_back({gltf, "no POSITION"});
    }
    {
        json gltf = triangleGltf();
        gltf["accessors"][1]["type"] = "VEC2";
        cases.push_back({gltf, "NORMAL: expected 3 components"});
    }
    {
        json gltf = triangleGltf();
        gltf["buffers"][0]["uri"] = "elsewhere.bin";
        cases.push_back({gltf, "triangle.gltf: "});
    }
    {
        json gltf = triangleGltf();
        gltf["nodes"][0]["children"] = {0};  // a cycle
        cases.push_back({gltf, "cycle"});
    }
    for (const auto& [gltf, expected] : cases) {
        auto mesh = readGltf(write("triangle.gltf", gltf));
        ASSERT_FALSE(mesh.ok()) << expected;
        EXPECT_NE(mesh.error().message.find("triangle.gltf"), std::string::npos);
        EXPECT_NE(mesh.error().message.find(expected), std::string::npos) << mesh.error().message;
        EXPECT_EQ(mesh.error().message.find('\n'), std::string::npos) << mesh.error().message;
    }
}

TEST_F(GltfFiles, TruncatedOrForeignFilesAreRefusedWithoutACrash) {
    const std::string text = triangleGltf().dump();
    std::ofstream(folder / "cut.gltf") << text.substr(0, text.size() / 2);
    std::ofstream(folder / "noise.glb") << "glTF\x02\0\0\0garbage that is not a binary glTF";
    std::filesystem::create_directory(folder / "folder.gltf");
    for (const char* name : {"cut.gltf", "noise.glb", "folder.gltf", "absent.gltf"}) {
        auto mesh = loadMesh((folder / name).string());
        ASSERT_FALSE(mesh.ok()) << name;
        EXPECT_NE(mesh.error().message.find(name), std::string::npos) << mesh.error().message;
        EXPECT_EQ(mesh.error().message.find('\n'), std::string::npos) << mesh.error().message;
    }
}

}  // namespace
}  // namespace matevo
