// Open and Save as can browse folders: the listing of the folder a typed path points into, and
// what a click on an entry makes of the path.
#include <fstream>

#include <gtest/gtest.h>
#include <imgui_internal.h>

#include "EditorUiFixture.h"
#include "FolderBrowser.h"

namespace matevo::testing {
namespace {

using ui::FolderEntry;

class FolderBrowser : public ::testing::Test {
protected:
    FolderBrowser() : dir(freshDirectory("browse")) {
        fs::create_directories(dir / "sub");
        for (const char* name : {"b.json", "a.json", ".hidden"}) std::ofstream(dir / name) << "{}";
    }
    ~FolderBrowser() override { fs::remove_all(dir); }
    fs::path dir;
};

TEST_F(FolderBrowser, ListsFoldersFirstThenFilesWithoutHiddenOnes) {
    const std::vector<FolderEntry> expected{
        {"..", true}, {"sub", true}, {"a.json", false}, {"b.json", false}};
    EXPECT_EQ(ui::listFolder(dir), expected);
    EXPECT_EQ(ui::browsedFolder((dir / "typed-name.json").string()), dir);
    EXPECT_TRUE(ui::listFolder(dir / "missing").empty());
}

TEST_F(FolderBrowser, AClickGoesIntoAFolderKeepingATypedNameOrTakesAFile) {
    const std::string typed = (dir / "new.json").string();
    EXPECT_EQ(ui::pathAfterChoosing(typed, {"sub", true}), (dir / "sub" / "new.json").string());
    EXPECT_EQ(ui::pathAfterChoosing((dir / "sub" / "").string(), {"..", true}),
              (dir / "").string());
    EXPECT_EQ(ui::pathAfterChoosing(typed, {"a.json", false}), (dir / "a.json").string());
}

TEST_F(FolderBrowser, ClickingAnEntryInTheListingEditsThePath) {
    HeadlessImGui imgui;
    std::string path = (dir / "new.json").string();
    bool chosen = false;
    const auto draw = [&] {
        ImGui::Begin("browse");
        chosen |= ui::drawFolderBrowser(path, 200.0f);
        ImGui::End();
    };
    imgui.frame(draw);
    ImGuiWindow* listing = HeadlessImGui::findWindow("browse/##folder");
    ASSERT_NE(listing, nullptr);
    const auto at = imgui.locate(*listing, ImHashStr("sub/", 0, listing->IDStack[0]), draw);
    ASSERT_TRUE(at.has_value());
    imgui.click(*at, draw);
    EXPECT_EQ(path, (dir / "sub" / "new.json").string());
    EXPECT_FALSE(chosen) << "a folder is not a choice";
}

}  // namespace
}  // namespace matevo::testing
