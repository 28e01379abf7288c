#include "LightingPanel.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <imgui.h>

#include "Widgets.h"
#include "scene/LightingChoice.h"

namespace matevo::ui {
namespace {

// The named lightings (scene/LightingChoice.h), then a file.
constexpr int kFileChoice = int(kLightings.size());

const char* comboLabel(int choice) {
    return choice == kFileChoice ? "HDR file" : kLightings[std::size_t(choice)].label.data();
}

int choiceIndex(const std::string& lighting) {
    for (int i = 0; i < kFileChoice; ++i)
        if (lighting == kLightings[std::size_t(i)].name) return i;
    return kFileChoice;
}

}  // namespace

std::string lightingAsChosen(const std::string& name) {
    if (choiceIndex(name) != kFileChoice) return name;
    std::error_code error;
    const std::filesystem::path file = std::filesystem::absolute(name, error);
    return error ? name : file.string();
}

bool drawLightingChoice(SceneSettings& scene, LightingView& view) {
    const std::string lighting = lightingChoiceOf(scene);
    const int current = choiceIndex(lighting);
    if (current == kFileChoice && view.hdrFile.empty()) view.hdrFile = lighting;
    bool changed = false;
    if (ImGui::BeginCombo("lighting", comboLabel(view.typingFile ? kFileChoice : current))) {
        for (int i = 0; i <= kFileChoice; ++i) {
            if (!ImGui::Selectable(comboLabel(i), i == current) || i == current) continue;
            // A file is applied once typed (Enter); a named lighting at once.
            view.typingFile = i == kFileChoice;
            if (i < kFileChoice) {
                setLightingChoice(std::string(kLightings[std::size_t(i)].name), scene);
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    hoverHint(
        "What every view draws in: the target, the grid, the inspector, the variant "
        "search and the Scene window; saved with the preset (scene.mode)");
    if (current != kFileChoice && !view.typingFile) return changed;
    char path[512];
    std::snprintf(path, sizeof path, "%s", view.hdrFile.c_str());
    if (ImGui::InputText("HDR file", path, sizeof path, ImGuiInputTextFlags_EnterReturnsTrue)) {
        view.hdrFile = path;
        if (!view.hdrFile.empty()) {
            setLightingChoice(lightingAsChosen(view.hdrFile), scene);
            view.typingFile = false;
            changed = true;
        }
    }
    hoverHint("A lat-long .hdr or .exr environment; Enter applies it");
    return changed;
}

void drawHoldUnderLightings(std::vector<std::string>& also, const std::string& chosen) {
    ImGui::TextUnformatted("hold under");
    for (const auto& lighting : kLightings) {
        const char* name = lighting.name.data();
        ImGui::SameLine();
        const bool isChosen = chosen == name;
        const auto found = std::find(also.begin(), also.end(), name);
        bool checked = isChosen || found != also.end();
        ImGui::BeginDisabled(isChosen);
        if (ImGui::Checkbox(name, &checked)) {
            if (checked && found == also.end()) also.emplace_back(name);
            if (!checked && found != also.end()) also.erase(found);
        }
        ImGui::EndDisabled();
    }
    hoverHint(
        "A variant counts only when it is in band and apart from the others under every "
        "checked lighting; the chosen lighting (the toolbar's) is always one of them");
}

std::vector<std::string> lightingsToHold(const std::string& chosen,
                                         const std::vector<std::string>& also) {
    std::vector<std::string> lightings{chosen};
    for (const std::string& name : also)
        if (std::find(lightings.begin(), lightings.end(), name) == lightings.end())
            lightings.push_back(name);
    if (lightings.size() == 1) lightings.clear();
    return lightings;
}

}  // namespace matevo::ui
