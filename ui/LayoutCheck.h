#pragma once
// Finds controls that the window cuts off: a panel (or a child region in it) whose widgets reach
// past its right edge, where there is no horizontal scrolling. Vertical overflow scrolls and is
// not reported. Reads ImGui's windows as the last frame left them.
#include <string>
#include <vector>

namespace matevo::ui {

// One line per cut-off window: "Controls: content 412 px wide in 360 px".
std::vector<std::string> findCutOffContent();

}  // namespace matevo::ui
