#include "mesh/ObjReader.h"

#include <fstream>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "mesh/MeshFile.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

void writeFile(const std::filesystem::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
}

// A unit cube's six faces as quads with normals and texture coordinates.
const char* kCube = R"(# cube
mtllib cube.mtl
o cube
v -1 -1  1
v  1 -1  1
v  1  1  1
v -1  1  1
v -1 -1 -1
v  1 -1 -1
v  1  1 -1
v -1  1 -1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
vn 0 0 -1
vn 1 0 0
vn -1 0 0
vn 0 1 0
vn 0 -1 0
usemtl paint
s off
f 1/1/1 2/2/1 3/3/1 4/4/1
f 6/1/2 5/2/2 8/3/2 7/4/2
f 2/1/3 6/2/3 7/3/3 3/4/3
f 5/1/4 1/2/4 4/3/4 8/4/4
f 4/1/5 3/2/5 7/3/5 8/4/5
f 5/1/6 6/2/6 2/3/6 1/4/6
)";

TEST(ObjReader, ReadsQuadsWithNormalsAndTextureCoordinates) {
    auto mesh = parseObj(kCube, "cube.obj");
    ASSERT_TRUE(mesh.ok()) << mesh.error().message;
    EXPECT_EQ(mesh->triangleCount(), 12u);
    EXPECT_EQ(mesh->vertices.size(), 24u);  // each corner once per face (its own normal)
    // The first face's corners: +z normal, OBJ's v flipped to our top-to-bottom rows.
    EXPECT_EQ(mesh->vertices[0].normal, glm::vec3(0, 0, 1));
    EXPECT_EQ(mesh->vertices[2].uv, glm::vec2(1, 0));
    EXPECT_EQ(mesh->vertices[0].uv, glm::vec2(0, 1));
}

TEST(ObjReader, NegativeIndicesAndMissingNormals) {
    auto mesh = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n", "tri.obj");
    ASSERT_TRUE(mesh.ok()) << mesh.error().message;
    ASSERT_EQ(mesh->triangleCount(), 1u);
    for (const MeshVertex& vertex : mesh->vertices)
        EXPECT_LT(glm::length(vertex.normal - glm::vec3(0, 0, 1)), 1e-6f);
}

TEST(ObjReader, BrokenFilesGiveOneLineNamingFileAndLine) {
    const std::pair<const char*, const char*> cases[] = {
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "tri.obj:4: position index 4 out of range"},
        {"v 0 0 zero\n", "tri.obj:1: 'zero' is not a finite number"},
        {"v 0 0\n", "tri.obj:1: 'v' needs 3 numbers"},
        {"v 0 0 0\nv 1 0 0\nf 1 2\n", "tri.obj:3: a face needs at least three corners"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\n",
         "tri.obj:4: texture coordinate index 1 out of range"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2/3/4 2 3\n", "has too many '/'"},
        {"# only a comment\n", "tri.obj: no faces"},
        {"\x89PNG\r\n\x1a\n\x01\x02", "tri.obj: no faces"},
    };
    for (const auto& [text, expected] : cases) {
        auto mesh = parseObj(text, "tri.obj");
        ASSERT_FALSE(mesh.ok()) << text;
        EXPECT_NE(mesh.error().message.find(expected), std::string::npos) << mesh.error().message;
        EXPECT_EQ(mesh.error().message.find('\n'), std::string::npos);
    }
}

TEST(ObjReader, LoadMeshReadsAFileAndFitsIt) {
    testing::ScratchFolder folder("obj");
    writeFile(folder / "cube.OBJ", kCube);
    auto mesh = loadMesh((folder / "cube.OBJ").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error().message;
    // Corners at distance sqrt(3) from the centre, scaled to 1.
    EXPECT_NEAR(glm::length(mesh->vertices[0].position), 1.0f, 1e-6f);

    auto missing = loadMesh((folder / "absent.obj").string());
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("absent.obj"), std::string::npos);
    auto wrongKind = loadMesh((folder / "cube.stl").string());
    ASSERT_FALSE(wrongKind.ok());
    EXPECT_NE(wrongKind.error().message.find("not a mesh"), std::string::npos);
}

}  // namespace
}  // namespace matevo
