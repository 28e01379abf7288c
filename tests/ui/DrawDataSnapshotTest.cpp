// What a frame would draw, compared with the frame on screen: an unchanged frame is equal, a
// change names only the pixels of the triangles that differ (every pixel outside the named
// areas is covered by the same triangles in the same order), and clipping restricts every
// command to an area in whole pixels.
#include "DrawDataSnapshot.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>

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

// Per framebuffer pixel, a hash of the triangles whose scissor and interior hold its centre, in
// drawing order (their vertices, texture and clip rectangle): two frames draw a pixel the same
// where these agree. Written apart from the snapshot, as a rasteriser would see the draw data.
struct Coverage {
    int width = 0, height = 0;
    std::vector<std::uint64_t> hashes;

    explicit Coverage(const ImDrawData& drawData)
        : width(int(drawData.DisplaySize.x)),
          height(int(drawData.DisplaySize.y)),
          hashes(std::size_t(width) * std::size_t(height), 0) {
        for (int l = 0; l < drawData.CmdListsCount; ++l) {
            const ImDrawList& list = *drawData.CmdLists[l];
            for (const ImDrawCmd& command : list.CmdBuffer) {
                if (command.UserCallback) continue;
                for (unsigned t = 0; t + 2 < command.ElemCount; t += 3) {
                    ImDrawVert corners[3];
                    for (unsigned c = 0; c < 3; ++c)
                        corners[c] = list.VtxBuffer[int(command.VtxOffset) +
                                                    list.IdxBuffer[int(command.IdxOffset + t + c)]];
                    cover(command, corners, drawData.DisplayPos);
                }
            }
        }
    }

    void cover(const ImDrawCmd& command, const ImDrawVert (&corners)[3], ImVec2 origin) {
        std::uint64_t id = 1469598103934665603ull;
        const auto mixBytes = [&id](const void* data, std::size_t size) {
            for (std::size_t i = 0; i < size; ++i)
                id = (id ^ static_cast<const unsigned char*>(data)[i]) * 1099511628211ull;
        };
        mixBytes(corners, sizeof corners);
        mixBytes(&command.ClipRect, sizeof command.ClipRect);
        mixBytes(&command.TextureId, sizeof command.TextureId);
        const float clipX0 = std::max(0.0f, command.ClipRect.x - origin.x);
        const float clipY0 = std::max(0.0f, command.ClipRect.y - origin.y);
        const float clipX1 = std::min(float(width), command.ClipRect.z - origin.x);
        const float clipY1 = std::min(float(height), command.ClipRect.w - origin.y);
        if (clipX1 <= clipX0 || clipY1 <= clipY0) return;
        const int x0 = int(clipX0), y0 = int(clipY0);
        const int x1 = x0 + int(clipX1 - clipX0), y1 = y0 + int(clipY1 - clipY0);
        ImVec2 p[3];
        for (int c = 0; c < 3; ++c)
            p[c] = ImVec2(corners[c].pos.x - origin.x, corners[c].pos.y - origin.y);
        const auto edge = [](ImVec2 a, ImVec2 b, float x, float y) {
            return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
        };
        const int left = std::max(x0, int(std::floor(std::min({p[0].x, p[1].x, p[2].x}))));
        const int right = std::min(x1, int(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))));
        const int top = std::max(y0, int(std::floor(std::min({p[0].y, p[1].y, p[2].y}))));
        const int bottom = std::min(y1, int(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))));
        for (int y = top; y < bottom; ++y)
            for (int x = left; x < right; ++x) {
                const float cx = float(x) + 0.5f, cy = float(y) + 0.5f;
                const float e0 = edge(p[0], p[1], cx, cy), e1 = edge(p[1], p[2], cx, cy),
                            e2 = edge(p[2], p[0], cx, cy);
                const bool inside =
                    (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
                if (!inside) continue;
                std::uint64_t& hash = hashes[std::size_t(y) * std::size_t(width) + std::size_t(x)];
                hash = (hash ^ id) * 1099511628211ull + 1;
            }
    }
};

// Pixels whose triangles differ between the two frames though no changed area holds them.
int missedPixels(const Coverage& before, const Coverage& after,
                 const std::vector<PixelArea>& changed) {
    int missed = 0;
    for (int y = 0; y < after.height; ++y)
        for (int x = 0; x < after.width; ++x) {
            const std::size_t at = std::size_t(y) * std::size_t(after.width) + std::size_t(x);
            if (before.hashes[at] == after.hashes[at]) continue;
            const bool named = std::any_of(changed.begin(), changed.end(), [&](const PixelArea& a) {
                return x >= a.x0 && x < a.x1 && y >= a.y0 && y < a.y1;
            });
            missed += !named;
        }
    return missed;
}

int pixelsOf(const std::vector<PixelArea>& areas) {
    int pixels = 0;
    for (const PixelArea& area : areas) pixels += (area.x1 - area.x0) * (area.y1 - area.y0);
    return pixels;
}

// Draws `before`'s frames until ImGui settles, then one frame of `after`: the areas named
// between the two frames, and the pixels they miss.
struct Change {
    std::vector<PixelArea> changed;
    int missed = 0;
};
Change changeBetween(HeadlessImGui& imgui, const std::function<void()>& before,
                     const std::function<void()>& after) {
    for (int i = 0; i < 3; ++i) imgui.frame(before);
    DrawDataSnapshot then;
    then.capture(*ImGui::GetDrawData());
    const Coverage thenCoverage(*ImGui::GetDrawData());
    imgui.frame(after);
    DrawDataSnapshot now;
    now.capture(*ImGui::GetDrawData());
    Change change;
    change.changed = now.changedSince(then);
    change.missed = missedPixels(thenCoverage, Coverage(*ImGui::GetDrawData()), change.changed);
    return change;
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

TEST(DrawDataSnapshot, AChangedDigitNamesItsGlyphsNotItsWindow) {
    HeadlessImGui imgui;
    TwoWindows before, after;
    before.counter = 41;
    after.counter = 42;
    const Change change = changeBetween(imgui, before, after);
    EXPECT_EQ(change.missed, 0);
    ASSERT_FALSE(change.changed.empty());
    // One glyph of the 13-pixel font, where the right window's text line is.
    EXPECT_LE(pixelsOf(change.changed), 20 * 20);
    for (const PixelArea& area : change.changed)
        EXPECT_TRUE(contains({400, 300, 600, 450}, area))
            << area.x0 << "," << area.y0 << " " << area.x1 << "," << area.y1;
}

// Whatever changes, no pixel whose triangles differ is left out.
TEST(DrawDataSnapshot, NoChangedPixelIsLeftOut) {
    HeadlessImGui imgui;
    // A text that grows and shifts what follows it, a progress bar, a checkbox, a text that
    // changes colour only.
    const auto panel = [](int counter, float progress, bool ticked) {
        return [=] {
            ImGui::SetNextWindowPos(ImVec2(10, 10));
            ImGui::SetNextWindowSize(ImVec2(300, 200));
            ImGui::Begin("Panel");
            ImGui::Text("generation %d of 50", counter);
            ImGui::ProgressBar(progress, ImVec2(-1, 0));
            bool tick = ticked;
            ImGui::Checkbox("heatmap", &tick);
            ImGui::TextColored(ticked ? ImVec4(1, 0.3f, 0.3f, 1) : ImVec4(0.3f, 1, 0.3f, 1),
                               "status");
            ImGui::Text("unchanging line");
            ImGui::End();
        };
    };
    const Change grown = changeBetween(imgui, panel(9, 0.2f, false), panel(10, 0.2f, false));
    EXPECT_EQ(grown.missed, 0);
    EXPECT_LE(pixelsOf(grown.changed), 40 * 20) << "the digits, not the lines below";
    const Change several = changeBetween(imgui, panel(10, 0.2f, false), panel(11, 0.6f, true));
    EXPECT_EQ(several.missed, 0);
    EXPECT_LT(pixelsOf(several.changed), 300 * 200 / 2);
    const Change shrunk = changeBetween(imgui, panel(11, 0.6f, true), panel(7, 0.0f, false));
    EXPECT_EQ(shrunk.missed, 0);

    // Overlapping windows: one comes to the front, then a window opens over both.
    const auto overlapping = [](const char* front, bool popup) {
        return [=] {
            for (const char* name : {"First", "Second"}) {
                const float at = name[0] == 'F' ? 50.0f : 150.0f;
                ImGui::SetNextWindowPos(ImVec2(at, at));
                ImGui::SetNextWindowSize(ImVec2(250, 200));
                ImGui::Begin(name);
                ImGui::Text("%s window", name);
                ImGui::End();
            }
            ImGui::SetWindowFocus(front);
            if (popup) {
                ImGui::SetNextWindowPos(ImVec2(120, 120));
                ImGui::SetNextWindowSize(ImVec2(120, 80));
                ImGui::Begin("Over");
                ImGui::Text("over both");
                ImGui::End();
            }
        };
    };
    const Change raised =
        changeBetween(imgui, overlapping("Second", false), overlapping("First", false));
    EXPECT_EQ(raised.missed, 0);
    EXPECT_FALSE(raised.changed.empty());
    const Change opened =
        changeBetween(imgui, overlapping("First", false), overlapping("First", true));
    EXPECT_EQ(opened.missed, 0);
    const Change closed =
        changeBetween(imgui, overlapping("First", true), overlapping("First", false));
    EXPECT_EQ(closed.missed, 0);
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

// Past the limit, neighbours merge first: two far clusters of small changes (a grid's tiles,
// a status line) stay two, and the empty screen between them is not drawn.
TEST(PixelArea, TooManyPiecesMergeWithTheirNearestNeighbours) {
    std::vector<PixelArea> areas;
    std::vector<PixelArea> added;
    for (int i = 0; i < int(ui::kMaxDisjointAreas); ++i) {
        added.push_back({10 * i, 0, 10 * i + 5, 5});                    // top left, a row
        added.push_back({1000 + 10 * i, 700, 1000 + 10 * i + 5, 705});  // bottom right
    }
    added.push_back({0, 3, 1200, 4});  // a thin line over the top row's gaps
    for (const PixelArea& area : added) ui::addDisjoint(areas, area);
    ASSERT_LE(areas.size(), ui::kMaxDisjointAreas);
    long long covered = 0;
    for (std::size_t i = 0; i < areas.size(); ++i) {
        covered += (long long)(areas[i].x1 - areas[i].x0) * (areas[i].y1 - areas[i].y0);
        for (std::size_t j = i + 1; j < areas.size(); ++j)
            EXPECT_TRUE(ui::intersect(areas[i], areas[j]).empty()) << i << " and " << j;
    }
    for (const PixelArea& area : added)  // every pixel added is held
        for (int y = area.y0; y < area.y1; ++y)
            for (int x = area.x0; x < area.x1; ++x)
                EXPECT_TRUE(std::any_of(areas.begin(), areas.end(),
                                        [&](const PixelArea& a) {
                                            return x >= a.x0 && x < a.x1 && y >= a.y0 && y < a.y1;
                                        }))
                    << x << "," << y;
    EXPECT_LT(covered, 20000) << "not the rectangle holding both clusters";
}

}  // namespace
}  // namespace matevo::testing
