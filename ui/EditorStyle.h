#pragma once
// The editor's look: colours, spacing and font, shared by the window and the headless tests (so
// the tests measure the layout the user sees). Call with a current ImGui context, before the
// font atlas is built.
namespace matevo::ui {

void applyEditorStyle();
// DejaVu Sans (a Debian default font, with the Greek ΔE and arrows) at 14 px; ImGui's built-in
// font when it is missing.
void loadEditorFont();

}  // namespace matevo::ui
