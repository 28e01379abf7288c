// What a frame would draw, compared with the frame on screen: an unchanged frame is equal, a
// change in one window names that window's pixels only, and clipping restricts every command
// to an area in whole pixels.
#include "DrawDataSnapshot.h"

#include <gtest/gtest.h>

#include "HeadlessImGui.h"

namespace matevo::testing {
namespace {

using ui::DrawDataSnapshot;
using ui::PixelArea;

// Two windows side by side; the right one shows a counter.
struct TwoWindows {
    int counter = 0;
    void operator()() const {
        ImGui::SetNextWindowPos(ImVec2(10, 10));
        ImGui::SetNextWindowSize(ImVec2(200, 150));
        ImGui::Begin("Left");
        ImGui::Text("unchanging");
        ImGui::End();
        ImGui::SetNextWindowPos(ImVec2(400, 300));
        ImGui::SetNextWindowSize(ImVec2(200, 150));
        ImGui::Begin("Right");
        ImGui::Text("counter %d", counter);
        ImGui::End();
    }
};

DrawDataSnapshot snapshotOf(HeadlessImGui& imgui, const TwoWindows& draw) {
    imgui.frame(draw);
    DrawDataSnapshot snapshot;
    snapshot.capture(*ImGui::GetDrawData());
    return snapshot;
}

bool contains(const PixelArea& outer, const PixelArea& inner) {
    return outer.x0 <= inner.x0 && outer.y0 <= inner.y0 && outer.x1 >= inner.x1 &&
           outer.y1 >= inner.y1;
}

TEST(DrawDataSnapshot, AnUnchangedFrameIsEqualAndChangesNothing) {
    HeadlessImGui imgui;
    TwoWindows draw;
    snapshotOf(imgui, draw);  // ImGui settles window sizes in its first frames
    const DrawDataSnapshot first = snapshotOf(imgui, draw);
    const DrawDataSnapshot second = snapshotOf(imgui, draw);
    EXPECT_TRUE(second == first);
    EXPECT_TRUE(second.changedSince(first).empty());
    EXPECT_EQ(first.whole(), (PixelArea{0, 0, 1280, 800}));
}

TEST(DrawDataSnapshot, AChangeInOneWindowNamesThatWindowsPixelsOnly) {
    HeadlessImGui imgui;
    TwoWindows draw;
    snapshotOf(imgui, draw);
    const DrawDataSnapshot before = snapshotOf(imgui, draw);
    draw.counter = 12345;
    const DrawDataSnapshot after = snapshotOf(imgui, draw);
    EXPECT_FALSE(after == before);
    const PixelArea changed = after.changedSince(before);
    EXPECT_FALSE(changed.empty());
    // The window, and the antialiased fringe of its border a pixel or two around it.
    EXPECT_TRUE(contains({396, 296, 604, 454}, changed)) << changed.x0 << "," << changed.y0
                                                          << " " << changed.x1 << ","
                                                          << changed.y1;
}

TEST(DrawDataSnapshot, ExtraBytesTheDisplayOrNothingBeforeMeanTheWholeFramebuffer) {
    HeadlessImGui imgui;
    TwoWindows draw;
    snapshotOf(imgui, draw);
    imgui.frame(draw);
    const float range[2] = {0.0f, 10.0f};
    const float otherRange[2] = {0.0f, 5.0f};
    DrawDataSnapshot before, after;
    before.capture(*ImGui::GetDrawData(), std::as_bytes(std::span(range)));
    after.capture(*ImGui::GetDrawData(), std::as_bytes(std::span(otherRange)));
    EXPECT_EQ(after.changedSince(before), after.whole());
    EXPECT_EQ(after.changedSince(DrawDataSnapshot{}), after.whole());
    before.clear();
    EXPECT_FALSE(before == before);  // a cleared snapshot equals nothing
}

TEST(DrawDataSnapshot, ClippingKeepsEachCommandsPixelsWithinTheArea) {
    HeadlessImGui imgui;
    TwoWindows draw;
    snapshotOf(imgui, draw);
    imgui.frame(draw);
    ImDrawData& drawData = *ImGui::GetDrawData();
    const PixelArea area{420, 310, 500, 400};
    ui::clipDrawData(drawData, area);
    int inside = 0;
    for (int l = 0; l < drawData.CmdListsCount; ++l)
        for (const ImDrawCmd& command : drawData.CmdLists[l]->CmdBuffer) {
            const ImVec4& clip = command.ClipRect;
            if (clip.z <= clip.x || clip.w <= clip.y) continue;  // drawn nowhere
            ++inside;
            EXPECT_TRUE(contains(area, {int(clip.x), int(clip.y), int(clip.z), int(clip.w)}));
            EXPECT_EQ(clip.x, float(int(clip.x)));  // whole pixels
            EXPECT_EQ(clip.w, float(int(clip.w)));
        }
    EXPECT_GT(inside, 0) << "the right window draws within the area";
}

}  // namespace
}  // namespace matevo::testing
