#include "DrawDataSnapshot.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace matevo::ui {
namespace {

// The scissor ImGui's Vulkan backend (and our image bridge) derive from a clip rectangle:
// clamped to the framebuffer, offset and extent truncated to whole pixels.
PixelArea scissorOf(const ImVec4& clip, const ImDrawData& drawData, const PixelArea& whole) {
    const float x0 = std::max(0.0f, clip.x - drawData.DisplayPos.x);
    const float y0 = std::max(0.0f, clip.y - drawData.DisplayPos.y);
    const float x1 = std::min(float(whole.x1), clip.z - drawData.DisplayPos.x);
    const float y1 = std::min(float(whole.y1), clip.w - drawData.DisplayPos.y);
    if (x1 <= x0 || y1 <= y0) return {};
    const int left = int(x0), top = int(y0);
    return {left, top, left + int(x1 - x0), top + int(y1 - y0)};
}

// Where a command can draw: the pixels of its vertices' bounding box within its scissor.
// (A window's first commands clip to the whole display, so the scissor alone says little.)
PixelArea drawnArea(const ImDrawList& list, const ImDrawCmd& command, const ImDrawData& drawData,
                    const PixelArea& whole) {
    const PixelArea scissor = scissorOf(command.ClipRect, drawData, whole);
    if (scissor.empty() || command.ElemCount == 0) return {};
    ImVec2 low(FLT_MAX, FLT_MAX), high(-FLT_MAX, -FLT_MAX);
    const ImDrawIdx* index = list.IdxBuffer.Data + command.IdxOffset;
    for (unsigned i = 0; i < command.ElemCount; ++i) {
        const ImVec2& p = list.VtxBuffer.Data[command.VtxOffset + index[i]].pos;
        low = ImVec2(std::min(low.x, p.x), std::min(low.y, p.y));
        high = ImVec2(std::max(high.x, p.x), std::max(high.y, p.y));
    }
    const PixelArea box{int(std::floor(low.x - drawData.DisplayPos.x)),
                        int(std::floor(low.y - drawData.DisplayPos.y)),
                        int(std::ceil(high.x - drawData.DisplayPos.x)),
                        int(std::ceil(high.y - drawData.DisplayPos.y))};
    return intersect(box, scissor);
}

}  // namespace

template <typename T>
void DrawDataSnapshot::append(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    appendBytes(&value, sizeof value);
}

void DrawDataSnapshot::appendBytes(const void* data, std::size_t size) {
    const std::size_t at = bytes_.size();
    bytes_.resize(at + size);
    if (size > 0) std::memcpy(bytes_.data() + at, data, size);
}

void DrawDataSnapshot::clear() {
    bytes_.clear();
    lists_.clear();
    headerEnd_ = 0;
}

void DrawDataSnapshot::capture(const ImDrawData& drawData, std::span<const std::byte> extra) {
    clear();
    unitScale_ = drawData.FramebufferScale.x == 1.0f && drawData.FramebufferScale.y == 1.0f;
    whole_ = {0, 0, int(drawData.DisplaySize.x * drawData.FramebufferScale.x),
              int(drawData.DisplaySize.y * drawData.FramebufferScale.y)};
    append(drawData.DisplayPos);
    append(drawData.DisplaySize);
    append(drawData.FramebufferScale);
    appendBytes(extra.data(), extra.size());
    headerEnd_ = bytes_.size();
    for (int l = 0; l < drawData.CmdListsCount; ++l) {
        const ImDrawList& list = *drawData.CmdLists[l];
        List kept{bytes_.size(), 0, {}};
        append(list.CmdBuffer.Size);
        // Field by field: ImDrawCmd has padding, whose bytes are not part of the picture.
        for (const ImDrawCmd& command : list.CmdBuffer) {
            append(command.ClipRect);
            append(command.TextureId);
            append(command.VtxOffset);
            append(command.IdxOffset);
            append(command.ElemCount);
            append(command.UserCallback);
            append(command.UserCallbackData);
            if (!command.UserCallback)
                kept.area = unite(kept.area, drawnArea(list, command, drawData, whole_));
        }
        static_assert(sizeof(ImDrawVert) == 2 * sizeof(ImVec2) + sizeof(ImU32), "no padding");
        append(list.VtxBuffer.Size);
        appendBytes(list.VtxBuffer.Data, std::size_t(list.VtxBuffer.Size) * sizeof(ImDrawVert));
        append(list.IdxBuffer.Size);
        appendBytes(list.IdxBuffer.Data, std::size_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
        kept.end = bytes_.size();
        lists_.push_back(kept);
    }
}

std::vector<PixelArea> DrawDataSnapshot::changedSince(const DrawDataSnapshot& before) const {
    const auto same = [&](std::size_t begin, std::size_t end, std::size_t otherBegin,
                          std::size_t otherEnd) {
        return end - begin == otherEnd - otherBegin &&
               std::memcmp(bytes_.data() + begin, before.bytes_.data() + otherBegin,
                           end - begin) == 0;
    };
    if (before.empty() || empty() || !unitScale_ ||
        !same(0, headerEnd_, 0, before.headerEnd_))
        return {whole_};
    // Lists are matched by position (ImGui orders them by window depth): a window that opens,
    // closes or comes to the front changes the lists after it, which are then redrawn whole.
    std::vector<PixelArea> changed;
    const std::size_t common = std::min(lists_.size(), before.lists_.size());
    for (std::size_t l = 0; l < common; ++l) {
        const List& now = lists_[l];
        const List& then = before.lists_[l];
        if (same(now.begin, now.end, then.begin, then.end)) continue;
        addDisjoint(changed, now.area);
        addDisjoint(changed, then.area);
    }
    for (std::size_t l = common; l < lists_.size(); ++l) addDisjoint(changed, lists_[l].area);
    for (std::size_t l = common; l < before.lists_.size(); ++l)
        addDisjoint(changed, before.lists_[l].area);
    return changed;
}

void clipDrawData(ImDrawData& drawData, std::span<const PixelArea> areas) {
    const PixelArea whole{0, 0, int(drawData.DisplaySize.x * drawData.FramebufferScale.x),
                          int(drawData.DisplaySize.y * drawData.FramebufferScale.y)};
    const ImVec2 origin = drawData.DisplayPos;
    for (int l = 0; l < drawData.CmdListsCount; ++l) {
        ImVector<ImDrawCmd>& commands = drawData.CmdLists[l]->CmdBuffer;
        ImVector<ImDrawCmd> clipped;
        for (const ImDrawCmd& command : commands) {
            if (command.UserCallback) {
                clipped.push_back(command);
                continue;
            }
            const PixelArea scissor = scissorOf(command.ClipRect, drawData, whole);
            for (const PixelArea& area : areas) {
                const PixelArea inside = intersect(scissor, area);
                if (inside.empty()) continue;
                ImDrawCmd part = command;
                part.ClipRect = ImVec4(float(inside.x0) + origin.x, float(inside.y0) + origin.y,
                                       float(inside.x1) + origin.x, float(inside.y1) + origin.y);
                clipped.push_back(part);
            }
        }
        commands.swap(clipped);
    }
}

}  // namespace matevo::ui
