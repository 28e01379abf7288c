// The Scene window's script verbs: what the instances wear and the mesh, checked when the
// script is read.
#include <gtest/gtest.h>

#include "EditorScript.h"

namespace matevo::editor {
namespace {

TEST(SceneScript, ShowAndMeshVerbsAreCheckedWhenTheScriptIsRead) {
    auto script = parseEditorScript(
        "scene-show kept\nscene-mesh /models/bunny.GLB\n"
        "scene-mesh knot\nwait-scene\n",
        "demo.txt");
    ASSERT_TRUE(script.ok()) << script.error().message;
    ASSERT_EQ(script->size(), 4u);
    EXPECT_EQ((*script)[0].kind, ScriptAction::Kind::SceneShow);
    EXPECT_EQ((*script)[0].text, "kept");
    EXPECT_EQ((*script)[1].kind, ScriptAction::Kind::SceneMesh);
    EXPECT_EQ((*script)[1].text, "/models/bunny.GLB");

    auto badSource = parseEditorScript("scene-show everything\n", "demo.txt");
    ASSERT_FALSE(badSource.ok());
    EXPECT_EQ(badSource.error().message,
              "demo.txt:1: scene-show: expected variants, kept or population, got 'everything'");
    auto badMesh = parseEditorScript("wait 1\nscene-mesh cube\n", "demo.txt");
    ASSERT_FALSE(badMesh.ok());
    EXPECT_NE(badMesh.error().message.find("demo.txt:2: scene-mesh: expected sphere, "
                                           "shaderball, knot or a .obj, .gltf or .glb file"),
              std::string::npos)
        << badMesh.error().message;
}

TEST(SceneScript, OrbitTakesItsNumberOfMoves) {
    auto script = parseEditorScript("scene-orbit 30\n", "demo.txt");
    ASSERT_TRUE(script.ok()) << script.error().message;
    EXPECT_EQ((*script)[0].kind, ScriptAction::Kind::SceneOrbit);
    EXPECT_EQ((*script)[0].first, 30);
    for (const char* bad : {"scene-orbit\n", "scene-orbit 0\n", "scene-orbit many\n"})
        EXPECT_FALSE(parseEditorScript(bad, "demo.txt").ok()) << bad;
    auto zero = parseEditorScript("scene-orbit 0\n", "demo.txt");
    ASSERT_FALSE(zero.ok());
    EXPECT_NE(zero.error().message.find("demo.txt:1: scene-orbit: must be in [1, "),
              std::string::npos)
        << zero.error().message;
}

}  // namespace
}  // namespace matevo::editor
