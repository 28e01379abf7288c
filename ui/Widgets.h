#pragma once
// Small widgets shared by the panels (imgui 1.86 lacks SeparatorText and friends).
#include <string>

#include <imgui.h>

namespace matevo::ui {

// A section title in the accent colour with a rule under it.
void sectionHeader(const char* title);

// A short grey explanation on hover of the previous item.
void hoverHint(const char* text);

// For the slider just drawn, which returned `changed`: its new value is final, so clamp and
// report it now. A dragged value is; a typed one (Ctrl+click) only when the field is left, so
// that typing "1000" is not judged at "1".
bool editFinished(bool changed);

// ImGui's SliderFloat and SliderInt, with the value drawn in the half of the frame the grab is
// not in: ImGui centres it, under the grab whenever the value is mid-range.
bool sliderFloat(const char* label, float* value, float min, float max, const char* format,
                 ImGuiSliderFlags flags = 0);
bool sliderInt(const char* label, int* value, int min, int max, const char* format = "%d",
               ImGuiSliderFlags flags = 0);

// Grey explanatory text, wrapped at the window's edge.
void mutedText(const std::string& text);

// Width of a widget of `itemWidth` with its label to the right (ImGui's default layout).
float labelledWidth(float itemWidth, const char* label);
// Width of a button with this label.
float buttonWidth(const char* label);
// SameLine() when an item `width` wide still fits on the current line, else a new line: toolbars
// wrap in narrow windows instead of cutting controls off.
void sameLineIfFits(float width);

// Where a floating window (Variants, Compare metrics) first opens: near the top left, `wanted`
// in size or less, so that it fits inside the editor's window (1024x640 at the smallest).
void placeFloatingWindow(ImVec2 wanted);

inline const ImVec4 kAccentColor = {0.45f, 0.72f, 1.0f, 1.0f};
inline const ImVec4 kMutedTextColor = {0.62f, 0.64f, 0.68f, 1.0f};
inline const ImVec4 kWarningColor = {1.0f, 0.78f, 0.35f, 1.0f};
inline const ImVec4 kErrorColor = {1.0f, 0.45f, 0.42f, 1.0f};

}  // namespace matevo::ui
