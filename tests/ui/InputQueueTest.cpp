// Input as events: a key tapped between two frames and a button released in the same frame as the
// pointer's last move both reach ImGui, where state polling (imgui 1.86's io.KeysDown,
// io.MouseDown) loses them.
#include "InputQueue.h"

#include <gtest/gtest.h>

#include "EditorUiFixture.h"

namespace matevo::testing {
namespace {

using ui::InputEvent;
using ui::InputQueue;
using Kind = InputEvent::Kind;

class InputEvents : public EditorUiTest {
protected:
    // Everything queued arrived between two frames; frames run until the queue is drained.
    void drain() {
        int frames = 0;
        do {
            queue.applyFrame(ImGui::GetIO());
            imgui.frame(draw);
        } while (queue.hasPending() && ++frames < 20);
        EXPECT_FALSE(queue.hasPending());
    }
    void key(int code, bool down) { queue.push({.kind = Kind::Key, .code = code, .down = down}); }
    void move(ImVec2 to) { queue.push({.kind = Kind::PointerMove, .position = to}); }
    void button(bool down) { queue.push({.kind = Kind::Button, .code = 0, .down = down}); }

    InputQueue queue;  // GLFW's key codes for the modifiers, as in the app
    const ui::ModifierKeys modifiers{};
};

TEST_F(InputEvents, CtrlZTappedWithinOneFrameUndoes) {
    const Preset original = ui.state().preset;
    const ImVec2 slider = locate("Controls", "Population");
    imgui.drag(slider, ImVec2(slider.x + 90, slider.y), draw);
    ASSERT_NE(ui.state().preset, original);

    key(modifiers.leftControl, true);
    key('Z', true);
    key('Z', false);
    key(modifiers.leftControl, false);
    drain();
    EXPECT_EQ(ui.state().preset, original);
}

TEST_F(InputEvents, TheSlidersLastValueLandsWhenReleasedInTheSameFrameAsTheLastMove) {
    const ImVec2 from = locate("Controls", "Population");
    const ImVec2 to(from.x + 100, from.y);
    // The value at `to`, dragged one step per frame.
    imgui.drag(from, to, draw);
    const int expected = ui.state().preset.ga.population;
    ui.undo();
    ASSERT_NE(ui.state().preset.ga.population, expected);

    // Polled state loses it: the release is seen with the final position in one frame.
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = from;
    imgui.frame(draw);
    io.MouseDown[0] = true;
    imgui.frame(draw);
    io.MousePos = to;
    io.MouseDown[0] = false;
    imgui.frame(draw);
    EXPECT_NE(ui.state().preset.ga.population, expected) << "state polling drops the last move";
    ui.undo();

    // As events: press, two moves and the release, all between the same two frames.
    move(from);
    drain();
    button(true);
    move(ImVec2(from.x + 50, from.y));
    move(to);
    button(false);
    drain();
    EXPECT_EQ(ui.state().preset.ga.population, expected);
}

TEST(InputQueue, KeepsTheOrderAndGivesEachChangeAFrame) {
    ImGuiContext* context = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    constexpr int keyA = 'A';  // the platform's code, as GLFW numbers letters
    InputQueue queue;
    queue.push({.kind = Kind::Key, .code = keyA, .down = true});
    queue.push({.kind = Kind::Character, .character = 'a'});
    queue.push({.kind = Kind::Key, .code = keyA, .down = false});
    queue.applyFrame(io);
    EXPECT_TRUE(io.KeysDown[keyA]);
    EXPECT_EQ(io.InputQueueCharacters.Size, 1);
    EXPECT_TRUE(queue.hasPending());
    queue.applyFrame(io);
    EXPECT_FALSE(io.KeysDown[keyA]);
    EXPECT_FALSE(queue.hasPending());
    ImGui::DestroyContext(context);
}

}  // namespace
}  // namespace matevo::testing
