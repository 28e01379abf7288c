// A main file and its content-named companions replaced as one (files/CompanionFiles.h), on real
// files. The kill -9 half of the promise is tests/fault/KillTest.cpp's export test.
#include "files/CompanionFiles.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "support/FileContents.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;
using testing::contentsOf;
using testing::namesIn;

TEST(CompanionFiles, TheNameFollowsTheContents) {
    const fs::path main = "/some/where/set.gltf";
    const CompanionFile a{"", ".bin", "bytes a"}, b{"", ".bin", "bytes b"};
    const std::string nameA = companionFileName(main, a);
    EXPECT_EQ(nameA.rfind("set.", 0), 0u) << nameA;
    EXPECT_EQ(nameA.size(), std::string("set.").size() + 16 + 4) << nameA;
    EXPECT_EQ(nameA.substr(nameA.size() - 4), ".bin");
    EXPECT_EQ(nameA, companionFileName("other/set.gltf", a));  // the folder plays no part
    EXPECT_NE(nameA, companionFileName(main, b));
    EXPECT_EQ(companionFileName(main, CompanionFile{"_roughness", ".png", "x"})
                  .rfind("set_roughness.", 0),
              0u);
}

TEST(CompanionFiles, ReplacingLeavesOnlyWhatTheNewMainFileNames) {
    testing::ScratchFolder folder("companions");
    const fs::path main = folder / "set.mtlx";
    std::ofstream(folder / "set.bin") << "a user's file";          // not a companion's name
    std::ofstream(folder / "set_roughness.png") << "another one";  // neither
    std::ofstream(folder / "other_roughness.0123456789abcdef.png") << "another set's";

    const CompanionFile colour1{"_base_color", ".png", "colour 1"};
    const CompanionFile rough1{"_roughness", ".png", "roughness 1"};
    ASSERT_TRUE(writeWithCompanions(main, "document 1", {colour1, rough1}).ok());
    EXPECT_EQ(contentsOf(main), "document 1");
    EXPECT_EQ(contentsOf(folder / companionFileName(main, colour1)), "colour 1");
    EXPECT_EQ(contentsOf(folder / companionFileName(main, rough1)), "roughness 1");

    // The colour stays, the roughness changes, and a kind not written this time goes away.
    const CompanionFile rough2{"_roughness", ".png", "roughness 2"};
    const CompanionFile noColour{"_base_color", ".png", ""};
    ASSERT_TRUE(writeWithCompanions(main, "document 2", {noColour, rough2}).ok());
    EXPECT_EQ(contentsOf(main), "document 2");
    EXPECT_EQ(namesIn(folder.path()),
              (std::set<std::string>{"set.mtlx", "set.bin", "set_roughness.png",
                                     "other_roughness.0123456789abcdef.png",
                                     companionFileName(main, rough2)}));
    EXPECT_EQ(contentsOf(folder / companionFileName(main, rough2)), "roughness 2");
}

TEST(CompanionFiles, AnOrphanLeftByAKillIsRemovedNextTime) {
    testing::ScratchFolder folder("companions");
    const fs::path main = folder / "set.gltf";
    const CompanionFile bin1{"", ".bin", "buffer 1"}, bin2{"", ".bin", "buffer 2"};
    ASSERT_TRUE(writeWithCompanions(main, "json 1", {bin1}).ok());
    // A writer killed after its companion and before its main file: the old pair is intact.
    std::ofstream(folder / companionFileName(main, bin2)) << "buffer 2";
    EXPECT_EQ(contentsOf(main), "json 1");
    EXPECT_EQ(contentsOf(folder / companionFileName(main, bin1)), "buffer 1");
    ASSERT_TRUE(writeWithCompanions(main, "json 1 again", {bin1}).ok());
    EXPECT_EQ(namesIn(folder.path()),
              (std::set<std::string>{"set.gltf", companionFileName(main, bin1)}));
}

TEST(CompanionFiles, AFailedCompanionLeavesTheOldMainFile) {
    testing::ScratchFolder folder("companions");
    const fs::path main = folder / "set.gltf";
    const CompanionFile bin1{"", ".bin", "buffer 1"}, bin2{"", ".bin", "buffer 2"};
    ASSERT_TRUE(writeWithCompanions(main, "json 1", {bin1}).ok());
    fs::create_directory(folder / companionFileName(main, bin2));  // cannot be written
    const Status status = writeWithCompanions(main, "json 2", {bin2});
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().message.find(companionFileName(main, bin2)), std::string::npos)
        << status.error().message;
    EXPECT_EQ(contentsOf(main), "json 1");
    EXPECT_EQ(contentsOf(folder / companionFileName(main, bin1)), "buffer 1");
}

}  // namespace
}  // namespace matevo
