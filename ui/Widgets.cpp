#include "Widgets.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include <imgui_internal.h>

namespace matevo::ui {
namespace {

// Where the grab of a slider over [min, max] sits for `value`, in [0, 1] of its frame.
double grabFraction(double value, double min, double max, ImGuiSliderFlags flags) {
    if (!(max > min)) return 0.0;
    const bool logarithmic = (flags & ImGuiSliderFlags_Logarithmic) && min > 0.0 && value > 0.0;
    const double fraction =
        logarithmic ? std::log(value / min) / std::log(max / min) : (value - min) / (max - min);
    return std::clamp(fraction, 0.0, 1.0);
}

// The slider with its own text hidden, then the value beside the grab and the label where ImGui
// puts it. The label keeps its ID (tests and the ini file find the slider by it) and the slider
// stays the last item, for IsItemHovered, editFinished and tooltips.
template <typename T>
bool sliderWithValueBeside(const char* label, T* value, T min, T max, const char* format,
                           ImGuiSliderFlags flags) {
    constexpr ImGuiDataType type =
        std::is_same_v<T, float> ? ImGuiDataType_Float : ImGuiDataType_S32;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float frameWidth = ImGui::CalcItemWidth();
    // Typing (Ctrl+click) shows ImGui's own text field, which must stay visible.
    const bool typing = ImGui::TempInputIsActive(ImGui::GetID(label));
    if (!typing) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0, 0, 0, 0));
    const bool changed = ImGui::SliderScalar(label, type, value, &min, &max, format, flags);
    if (!typing) ImGui::PopStyleColor();
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const ImVec2 frameMin = ImGui::GetItemRectMin();
    const ImVec2 frameMax(frameMin.x + frameWidth, frameMin.y + ImGui::GetFrameHeight());
    const ImU32 textColour = ImGui::GetColorU32(ImGuiCol_Text);
    if (!typing) {
        char text[64];
        const char* end =
            text + ImGui::DataTypeFormatString(text, sizeof text, type, value, format);
        const float textWidth = ImGui::CalcTextSize(text, end).x;
        const double grab = grabFraction(double(*value), double(min), double(max), flags);
        const float x = grab < 0.5 ? frameMax.x - style.FramePadding.x - textWidth
                                   : frameMin.x + style.FramePadding.x;
        drawList.PushClipRect(frameMin, frameMax, true);
        drawList.AddText(ImVec2(x, frameMin.y + style.FramePadding.y), textColour, text, end);
        drawList.PopClipRect();
    }
    if (const char* labelEnd = ImGui::FindRenderedTextEnd(label); labelEnd != label)
        drawList.AddText(
            ImVec2(frameMax.x + style.ItemInnerSpacing.x, frameMin.y + style.FramePadding.y),
            textColour, label, labelEnd);
    return changed;
}

}  // namespace

bool sliderFloat(const char* label, float* value, float min, float max, const char* format,
                 ImGuiSliderFlags flags) {
    return sliderWithValueBeside(label, value, min, max, format, flags);
}

bool sliderInt(const char* label, int* value, int min, int max, const char* format,
               ImGuiSliderFlags flags) {
    return sliderWithValueBeside(label, value, min, max, format, flags);
}

void sectionHeader(const char* title) {
    ImGui::Spacing();
    ImGui::TextColored(kAccentColor, "%s", title);
    ImGui::Separator();
}

void hoverHint(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

void mutedText(const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, kMutedTextColor);
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

float labelledWidth(float itemWidth, const char* label) {
    const float text = ImGui::CalcTextSize(label, nullptr, true).x;
    return itemWidth + (text > 0.0f ? ImGui::GetStyle().ItemInnerSpacing.x + text : 0.0f);
}

float buttonWidth(const char* label) {
    return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

void sameLineIfFits(float width) {
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    const float next = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
    if (next <= right) ImGui::SameLine();
}

bool editFinished(bool changed) {
    if (ImGui::IsItemDeactivatedAfterEdit()) return true;
    return changed && !ImGui::TempInputIsActive(ImGui::GetItemID());
}

void placeFloatingWindow(ImVec2 wanted) {
    constexpr float kMargin = 40.0f;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(kMargin, kMargin), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(std::min(wanted.x, display.x - 2.0f * kMargin),
                                    std::min(wanted.y, display.y - 2.0f * kMargin)),
                             ImGuiCond_FirstUseEver);
}

}  // namespace matevo::ui
