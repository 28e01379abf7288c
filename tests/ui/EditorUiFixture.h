#pragma once
// The editor UI in a headless ImGui context, opened on the shipped validation metal preset with a
// scratch folder standing in for the user's preset folder.
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "EditorUi.h"
#include "HeadlessImGui.h"
#include "documents/Preset.h"

namespace matevo::testing {

using ui::EditorUi;
using ui::FrameRequests;
using ui::PresetFolders;
namespace fs = std::filesystem;

inline const fs::path kShippedFolder = fs::path(MATEVO_SOURCE_DIR) / "presets";
inline const fs::path kShippedMetal = kShippedFolder / "validation_metal.json";

inline Preset validationMetal() {
    auto loaded = loadPreset(kShippedMetal);
    EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error().message);
    return loaded->preset;
}

inline fs::path freshDirectory(const std::string& name) {
    auto dir = fs::temp_directory_path() / ("matevo_ui_" + name + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

inline std::string fileText(const fs::path& file) {
    std::ifstream in(file);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

class EditorUiTest : public ::testing::Test {
protected:
    EditorUiTest()
        : userFolder(freshDirectory("user")),
          ui(validationMetal(), kShippedMetal,
             PresetFolders{kShippedFolder, userFolder / "presets", userFolder / "exports"}) {
        imgui.frame(draw);
    }
    ~EditorUiTest() override { fs::remove_all(userFolder); }

    fs::path userFolder;
    HeadlessImGui imgui;
    EditorUi ui;
    FrameRequests lastRequests;
    bool quitRequested = false;  // in any frame so far
    std::function<void()> draw = [this] {
        lastRequests = ui.draw();
        quitRequested |= lastRequests.quit;
    };

    ImVec2 locate(const char* window, const char* label) {
        auto point = imgui.locate(window, label, draw);
        EXPECT_TRUE(point.has_value()) << label << " not found in " << window;
        return point.value_or(ImVec2(-1, -1));
    }
};

}  // namespace matevo::testing
