// Nothing the user made is lost without asking: open, quit, close and a dropped file ask first;
// shipped presets stay read-only; "Save as" starts in the user's folder; undo past a save keeps
// the file name and contents consistent; a save into a missing folder creates it or says why.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "EditorUiFixture.h"
#include "UnsavedChangesPrompt.h"

namespace matevo::testing {
namespace {

using ui::UnsavedChangesPrompt;

class NeverLoseWork : public EditorUiTest {
protected:
    // An edit as a user makes it: the population slider dragged.
    void editSomething() {
        const ImVec2 slider = locate("Controls", "Population");
        imgui.drag(slider, ImVec2(slider.x + 90, slider.y), draw);
        ASSERT_TRUE(ui.state().hasUnsavedChanges());
    }
    bool promptShown() {
        ImGuiWindow* prompt = ImGui::FindWindowByName(UnsavedChangesPrompt::kTitle);
        return prompt && prompt->Active;
    }
    void answer(const char* button) {
        imgui.frame(draw);  // a new popup sizes itself in its first, hidden frame
        ASSERT_TRUE(promptShown());
        imgui.click(locate(UnsavedChangesPrompt::kTitle, button), draw);
        imgui.frame(draw);
    }
    Preset otherPreset(const fs::path& file) {
        Preset other = validationMetal();
        other.name = "other";
        other.ga.population = 61;
        EXPECT_TRUE(savePreset(other, file).ok());
        return other;
    }
};

TEST_F(NeverLoseWork, CtrlOAsksFirstAndCancelKeepsTheEdits) {
    editSomething();
    const Preset edited = ui.state().preset;
    imgui.pressKey('O', /*ctrl=*/true, /*shift=*/false, draw);
    EXPECT_TRUE(promptShown());
    EXPECT_EQ(ImGui::FindWindowByName("Open preset"), nullptr) << "no open dialog before asking";
    answer("Cancel");
    EXPECT_FALSE(promptShown());
    EXPECT_EQ(ui.state().preset, edited);
    EXPECT_TRUE(ui.state().hasUnsavedChanges());
}

TEST_F(NeverLoseWork, CtrlQAsksFirstAndQuitsOnlyWhenDiscarded) {
    editSomething();
    imgui.pressKey('Q', true, false, draw);
    EXPECT_FALSE(quitRequested);
    EXPECT_TRUE(promptShown());
    answer("Cancel");
    EXPECT_FALSE(quitRequested);

    ui.requestQuit();  // the window's close button goes the same way
    imgui.frame(draw);
    imgui.frame(draw);
    EXPECT_FALSE(quitRequested);
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = *imgui.locate(UnsavedChangesPrompt::kTitle, "Discard", draw);
    imgui.frame(draw);
    io.MouseDown[0] = true;
    imgui.frame(draw);
    io.MouseDown[0] = false;
    imgui.frame(draw);
    EXPECT_TRUE(quitRequested);
}

TEST_F(NeverLoseWork, QuitWithoutChangesDoesNotAsk) {
    imgui.pressKey('Q', true, false, draw);
    EXPECT_TRUE(quitRequested);
    EXPECT_FALSE(promptShown());
}

TEST_F(NeverLoseWork, ADroppedFileAsksAndSaveAsKeepsTheWorkBeforeOpeningIt) {
    const fs::path dropped = userFolder / "dropped.json";
    const Preset other = otherPreset(dropped);
    editSomething();
    const Preset edited = ui.state().preset;
    ui.requestOpen(dropped);
    imgui.frame(draw);
    EXPECT_NE(ui.state().preset, other) << "not opened before the user answers";
    // "Save": the document is a shipped preset, so this goes through "Save as".
    answer("Save");
    imgui.frame(draw);
    ImGuiWindow* saveAs = ImGui::FindWindowByName("Save preset as");
    ASSERT_TRUE(saveAs && saveAs->Active);
    imgui.pressKey(ImGui::GetIO().KeyMap[ImGuiKey_Enter], false, false, draw);
    imgui.frame(draw);
    const fs::path copy = userFolder / "presets" / "validation_metal.json";
    ASSERT_TRUE(fs::exists(copy)) << ui.state().status.latest().text;
    auto saved = loadPreset(copy);
    ASSERT_TRUE(saved.ok()) << saved.error().message;
    EXPECT_EQ(saved->preset.ga, edited.ga);
    EXPECT_EQ(ui.state().preset, other) << "then the dropped file opened";
    EXPECT_EQ(ui.state().presetPath, dropped);
}

TEST_F(NeverLoseWork, ShippedPresetsAreReadOnlyAndSaveAsStartsInTheUserFolder) {
    const std::string shippedBefore = fileText(kShippedMetal);
    editSomething();
    imgui.pressKey('S', /*ctrl=*/true, /*shift=*/false, draw);
    imgui.frame(draw);
    EXPECT_EQ(fileText(kShippedMetal), shippedBefore);
    ImGuiWindow* saveAs = ImGui::FindWindowByName("Save preset as");
    ASSERT_TRUE(saveAs && saveAs->Active) << "Ctrl+S on a shipped preset asks where";
    EXPECT_NE(ui.state().status.latest().text.find("read-only"), std::string::npos);
    // One Enter saves into the user's folder, never over the shipped file.
    imgui.pressKey(ImGui::GetIO().KeyMap[ImGuiKey_Enter], false, false, draw);
    EXPECT_EQ(fileText(kShippedMetal), shippedBefore);
    EXPECT_EQ(ui.state().presetPath, userFolder / "presets" / "validation_metal.json");
    EXPECT_FALSE(ui.state().hasUnsavedChanges());

    // Typing the shipped path on purpose is refused too, with the reason.
    EXPECT_FALSE(ui.savePreset(kShippedMetal));
    EXPECT_EQ(fileText(kShippedMetal), shippedBefore);
    EXPECT_NE(ui.state().status.latest().text.find("read-only"), std::string::npos);
}

// Save as onto another existing file asks first; "Choose another" leaves it untouched.
TEST_F(NeverLoseWork, SaveAsAsksBeforeReplacingAnotherFile) {
    fs::create_directories(userFolder / "presets");
    const fs::path existing = userFolder / "presets" / "validation_metal.json";
    otherPreset(existing);
    const std::string before = fileText(existing);
    editSomething();
    imgui.pressKey('S', /*ctrl=*/true, /*shift=*/true, draw);  // suggests `existing`
    imgui.frame(draw);
    imgui.pressKey(ImGui::GetIO().KeyMap[ImGuiKey_Enter], false, false, draw);
    EXPECT_EQ(fileText(existing), before) << "replaced without asking";
    imgui.click(locate("Save preset as", "Choose another"), draw);
    EXPECT_EQ(fileText(existing), before);
    EXPECT_TRUE(ui.state().hasUnsavedChanges());
    imgui.frame(draw);
    imgui.frame(draw);
    imgui.pressKey(ImGui::GetIO().KeyMap[ImGuiKey_Enter], false, false, draw);
    imgui.click(locate("Save preset as", "Replace"), draw);
    EXPECT_NE(fileText(existing), before);
    EXPECT_EQ(ui.state().presetPath, existing);
    EXPECT_FALSE(ui.state().hasUnsavedChanges());
}

TEST_F(NeverLoseWork, SavedCopyKeepsFindingTheShippedTextures) {
    auto painted = loadPreset(kShippedFolder / "validation_painted_metal.json");
    ASSERT_TRUE(painted.ok());
    ASSERT_FALSE(painted->preset.roughnessTexture.empty());
    EditorUi paintedUi(
        painted->preset, kShippedFolder / "validation_painted_metal.json",
        PresetFolders{kShippedFolder, userFolder / "presets", userFolder / "exports"});
    const fs::path copy = userFolder / "presets" / "painted.json";
    ASSERT_TRUE(paintedUi.savePreset(copy));
    auto reloaded = loadPreset(copy);
    ASSERT_TRUE(reloaded.ok());
    EXPECT_TRUE(fs::exists(copy.parent_path() / reloaded->preset.roughnessTexture))
        << reloaded->preset.roughnessTexture;
}

TEST_F(NeverLoseWork, UndoPastSaveAsReturnsToTheOldFileAndCtrlSCannotOverwriteTheNewOne) {
    // Promote a candidate, save it as a variant, undo the promotion, Ctrl+S.
    Genome variant = ui.state().preset.target;
    variant[kAlpha1] = 0.05;
    ui.state().evolution.candidates = {{1, 0.1, 2.0, variant, nullptr, nullptr}};
    imgui.frame(draw);
    imgui.click(locate("Inspect", "Promote to target"), draw);
    ASSERT_EQ(ui.state().preset.target, variant);
    const fs::path saved = userFolder / "variant.json";
    ASSERT_TRUE(ui.savePreset(saved));
    const std::string variantText = fileText(saved);

    imgui.pressKey('Z', /*ctrl=*/true, /*shift=*/false, draw);
    EXPECT_NE(ui.state().preset.target, variant);
    EXPECT_EQ(ui.state().presetPath, kShippedMetal) << "the undone state belongs to the old file";
    EXPECT_FALSE(ui.state().hasUnsavedChanges()) << "it is exactly what that file holds";
    imgui.pressKey('S', true, false, draw);
    imgui.frame(draw);
    EXPECT_EQ(fileText(saved), variantText) << "the saved variant is untouched";

    // Redo (Ctrl+Shift+Z) returns to the variant and its file, saved.
    if (ImGuiWindow* dialog = ImGui::FindWindowByName("Save preset as"); dialog && dialog->Active)
        imgui.pressKey(ImGui::GetIO().KeyMap[ImGuiKey_Escape], false, false, draw);
    imgui.pressKey('Z', /*ctrl=*/true, /*shift=*/true, draw);
    EXPECT_EQ(ui.state().preset.target, variant);
    EXPECT_EQ(ui.state().presetPath, saved);
    EXPECT_FALSE(ui.state().hasUnsavedChanges());
}

TEST_F(NeverLoseWork, UndoAfterSavingInPlaceMarksTheDocumentUnsaved) {
    const fs::path file = userFolder / "mine.json";
    ASSERT_TRUE(ui.savePreset(file));
    editSomething();
    imgui.pressKey('S', true, false, draw);
    ASSERT_FALSE(ui.state().hasUnsavedChanges());
    imgui.pressKey('Z', true, false, draw);
    EXPECT_EQ(ui.state().presetPath, file);
    EXPECT_TRUE(ui.state().hasUnsavedChanges()) << "the file holds the edit; the window does not";
}

TEST_F(NeverLoseWork, SaveCreatesMissingFoldersOrSaysWhyInFull) {
    const fs::path nested = userFolder / "a" / "b" / "deep.json";
    EXPECT_TRUE(ui.savePreset(nested)) << ui.state().status.latest().text;
    EXPECT_TRUE(fs::exists(nested));

    std::ofstream(userFolder / "plainfile") << "x";
    const fs::path impossible = userFolder / "plainfile" / "sub" / "x.json";
    EXPECT_FALSE(ui.savePreset(impossible));
    const std::string message = ui.state().status.latest().text;
    EXPECT_NE(message.find((userFolder / "plainfile" / "sub").string()), std::string::npos)
        << message;
    EXPECT_NE(message.find("Not a directory"), std::string::npos) << message;
    EXPECT_EQ(ui.state().status.latest().kind, ui::StatusKind::Error);
}

}  // namespace
}  // namespace matevo::testing
