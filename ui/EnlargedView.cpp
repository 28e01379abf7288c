#include "EnlargedView.h"

#include <algorithm>

#include "ImageView.h"
#include "Widgets.h"

namespace matevo::ui {

void drawEnlargedView(EditorState& state, const PanelRect& over, float imageSize) {
    const CandidateView* candidate = state.inspectedCandidate();
    if (!state.enlarged || !candidate) {
        state.enlarged = false;
        return;
    }
    ImGui::SetNextWindowPos(over.position, ImGuiCond_Always);
    ImGui::SetNextWindowSize(over.size, ImGuiCond_Always);
    constexpr ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                        ImGuiWindowFlags_NoCollapse |
                                        ImGuiWindowFlags_NoSavedSettings;
    if (ImGui::Begin("Enlarged candidate", &state.enlarged, kFlags)) {
        if (ImGui::IsWindowAppearing()) ImGui::SetWindowFocus();
        ImGui::Text("#%d   fitness %.4f   mean ΔE00 %.2f", candidate->rank, candidate->fitness,
                    candidate->meanDeltaE00);
        sameLineIfFits(ImGui::CalcTextSize("at the target's size; Esc closes").x);
        mutedText("at the target's size; Esc closes");
        const ImVec2 available = ImGui::GetContentRegionAvail();
        const float size = std::max(32.0f, std::min({imageSize, available.x, available.y}));
        ImVec2 at = ImGui::GetCursorScreenPos();
        at.x += std::max(0.0f, (available.x - size) * 0.5f);
        drawImage(*ImGui::GetWindowDrawList(), at, size, candidate->image,
                  state.heatmap.enabled ? candidate->heatmap : nullptr, state.heatmap.opacity);
        ImGui::InvisibleButton("enlarged", ImVec2(available.x, size));
        if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(0)) state.enlarged = false;
    }
    ImGui::End();
}

}  // namespace matevo::ui
