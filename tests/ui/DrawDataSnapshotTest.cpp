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
    const std::vector<PixelArea> changed = after.changedSince(before);
    EXPECT_FALSE(changed.empty());
    // The window, and the antialiased fringe of its border a pixel or two around it.
    for (const PixelArea& area : changed)
        EXPECT_TRUE(contains({396, 296, 604, 454}, area))
            << area.x0 << "," << area.y0 << " " << area.x1 << "," << area.y1;
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
    const std::vector<PixelArea> whole{after.whole()};
    EXPECT_EQ(after.changedSince(before), whole);
    EXPECT_EQ(after.changedSince(DrawDataSnapshot{}), whole);
    before.clear();
    EXPECT_FALSE(before == before);  // a cleared snapshot equals nothing
}

TEST(DrawDataSnapshot, ClippingKeepsEachCommandsPixelsWithinOneArea) {
    HeadlessImGui imgui;
    TwoWindows draw;
    snapshotOf(imgui, draw);
    imgui.frame(draw);
    ImDrawData& drawData = *ImGui::GetDrawData();
    int commandsBefore = 0;
    for (int l = 0; l < drawData.CmdListsCount; ++l)
        commandsBefore += drawData.CmdLists[l]->CmdBuffer.Size;
    // Over parts of both windows.
    const PixelArea areas[] = {{420, 310, 500, 400}, {20, 20, 100, 60}};
    ui::clipDrawData(drawData, areas);
    int reaching[2] = {0, 0};
    int commandsAfter = 0;
    for (int l = 0; l < drawData.CmdListsCount; ++l)
        for (const ImDrawCmd& command : drawData.CmdLists[l]->CmdBuffer) {
            ++commandsAfter;
            const ImVec4& clip = command.ClipRect;
            const PixelArea scissor{int(clip.x), int(clip.y), int(clip.z), int(clip.w)};
            EXPECT_EQ(clip.x, float(scissor.x0));  // whole pixels
            EXPECT_EQ(clip.w, float(scissor.y1));
            EXPECT_FALSE(scissor.empty()) << "commands outside every area are dropped";
            const bool inFirst = contains(areas[0], scissor);
            const bool inSecond = contains(areas[1], scissor);
            EXPECT_TRUE(inFirst != inSecond) << "within exactly one area";
            ++reaching[inFirst ? 0 : 1];
        }
    EXPECT_GT(reaching[0], 0) << "the right window draws within the first area";
    EXPECT_GT(reaching[1], 0) << "the left window draws within the second";
    EXPECT_LE(commandsAfter, 2 * commandsBefore);
}

TEST(PixelArea, AddingKeepsTheSetDisjointAndCoversTheUnion) {
    std::vector<PixelArea> areas;
    ui::addDisjoint(areas, {0, 0, 100, 100});
    ui::addDisjoint(areas, {50, 50, 150, 150});  // overlaps the first
    ui::addDisjoint(areas, {10, 10, 20, 20});    // inside the first: adds nothing
    ui::addDisjoint(areas, {});                  // empty: adds nothing
    int pixels = 0;
    for (std::size_t i = 0; i < areas.size(); ++i) {
        pixels += (areas[i].x1 - areas[i].x0) * (areas[i].y1 - areas[i].y0);
        for (std::size_t j = i + 1; j < areas.size(); ++j)
            EXPECT_TRUE(ui::intersect(areas[i], areas[j]).empty()) << i << " and " << j;
    }
    EXPECT_EQ(pixels, 100 * 100 + 100 * 100 - 50 * 50);  // the union, each pixel once
}

TEST(PixelArea, TooManyPiecesBecomeTheRectangleHoldingThemAll) {
    std::vector<PixelArea> areas;
    for (int i = 0; i < int(ui::kMaxDisjointAreas) + 1; ++i)
        ui::addDisjoint(areas, {10 * i, 0, 10 * i + 5, 5});
    ASSERT_EQ(areas.size(), 1u);
    EXPECT_EQ(areas[0], (PixelArea{0, 0, 10 * int(ui::kMaxDisjointAreas) + 5, 5}));
}

}  // namespace
}  // namespace matevo::testing
