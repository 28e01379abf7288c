#include "DrawDataSnapshot.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "SequenceDiff.h"

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
    commands_.clear();
    headerEnd_ = 0;
}

void DrawDataSnapshot::capture(const ImDrawData& drawData, std::span<const std::byte> extra) {
    clear();
    unitScale_ = drawData.FramebufferScale.x == 1.0f && drawData.FramebufferScale.y == 1.0f;
    whole_ = {0, 0, int(drawData.DisplaySize.x * drawData.FramebufferScale.x),
              int(drawData.DisplaySize.y * drawData.FramebufferScale.y)};
    origin_ = drawData.DisplayPos;
    append(drawData.DisplayPos);
    append(drawData.DisplaySize);
    append(drawData.FramebufferScale);
    appendBytes(extra.data(), extra.size());
    headerEnd_ = bytes_.size();
    for (int l = 0; l < drawData.CmdListsCount; ++l) {
        const ImDrawList& list = *drawData.CmdLists[l];
        List kept{bytes_.size(), 0, {}, commands_.size(), std::size_t(list.CmdBuffer.Size), 0, 0};
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
            commands_.push_back({command.ClipRect, command.TextureId, command.UserCallback,
                                 command.UserCallbackData, command.VtxOffset, command.IdxOffset,
                                 command.ElemCount, scissorOf(command.ClipRect, drawData, whole_)});
        }
        static_assert(sizeof(ImDrawVert) == 2 * sizeof(ImVec2) + sizeof(ImU32), "no padding");
        append(list.VtxBuffer.Size);
        kept.vertices = bytes_.size();
        appendBytes(list.VtxBuffer.Data, std::size_t(list.VtxBuffer.Size) * sizeof(ImDrawVert));
        append(list.IdxBuffer.Size);
        kept.indices = bytes_.size();
        appendBytes(list.IdxBuffer.Data, std::size_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
        kept.end = bytes_.size();
        lists_.push_back(kept);
    }
}

std::vector<PixelArea> DrawDataSnapshot::changedSince(const DrawDataSnapshot& before) const {
    const auto same = [&](std::size_t begin, std::size_t end, std::size_t otherBegin,
                          std::size_t otherEnd) {
        return end - begin == otherEnd - otherBegin &&
               std::memcmp(bytes_.data() + begin, before.bytes_.data() + otherBegin, end - begin) ==
                   0;
    };
    if (before.empty() || empty() || !unitScale_ || !same(0, headerEnd_, 0, before.headerEnd_))
        return {whole_};
    // Lists are matched by position (ImGui orders them by window depth): a window that opens,
    // closes or comes to the front changes the lists after it. Comparing the triangles of two
    // different windows is still right, only less sparing.
    std::vector<PixelArea> changed;
    const std::size_t common = std::min(lists_.size(), before.lists_.size());
    for (std::size_t l = 0; l < common; ++l) {
        const List& now = lists_[l];
        const List& then = before.lists_[l];
        if (same(now.begin, now.end, then.begin, then.end)) continue;
        for (const PixelArea& area : changedAreas(now, before, then)) addDisjoint(changed, area);
    }
    for (std::size_t l = common; l < lists_.size(); ++l) addDisjoint(changed, lists_[l].area);
    for (std::size_t l = common; l < before.lists_.size(); ++l)
        addDisjoint(changed, before.lists_[l].area);
    return changed;
}

std::vector<DrawDataSnapshot::Primitive> DrawDataSnapshot::primitives(const List& list) const {
    std::vector<Primitive> primitives;
    for (std::size_t c = list.firstCommand; c < list.firstCommand + list.commandCount; ++c) {
        const Command& command = commands_[c];
        if (command.callback) {
            primitives.push_back({c, 0});
            continue;
        }
        for (unsigned t = 0; t < command.elementCount / 3; ++t) primitives.push_back({c, t});
    }
    return primitives;
}

ImDrawVert DrawDataSnapshot::vertex(const List& list, const Command& command,
                                    unsigned element) const {
    ImDrawIdx index;
    std::memcpy(&index,
                bytes_.data() + list.indices + (command.indexOffset + element) * sizeof(ImDrawIdx),
                sizeof index);
    ImDrawVert vertex;
    std::memcpy(&vertex,
                bytes_.data() + list.vertices +
                    (command.vertexOffset + std::size_t(index)) * sizeof(ImDrawVert),
                sizeof vertex);
    return vertex;
}

bool DrawDataSnapshot::samePrimitive(const List& list, const Primitive& primitive,
                                     const DrawDataSnapshot& other, const List& otherList,
                                     const Primitive& otherPrimitive) const {
    const Command& command = commands_[primitive.command];
    const Command& otherCommand = other.commands_[otherPrimitive.command];
    if (command.callback || otherCommand.callback)
        return command.callback == otherCommand.callback &&
               command.callbackData == otherCommand.callbackData &&
               std::memcmp(&command.clipRect, &otherCommand.clipRect, sizeof(ImVec4)) == 0;
    if (command.texture != otherCommand.texture ||
        std::memcmp(&command.clipRect, &otherCommand.clipRect, sizeof(ImVec4)) != 0)
        return false;
    for (unsigned corner = 0; corner < 3; ++corner) {
        const ImDrawVert a = vertex(list, command, 3 * primitive.triangle + corner);
        const ImDrawVert b =
            other.vertex(otherList, otherCommand, 3 * otherPrimitive.triangle + corner);
        if (std::memcmp(&a, &b, sizeof a) != 0) return false;
    }
    return true;
}

PixelArea DrawDataSnapshot::primitiveArea(const List& list, const Primitive& primitive) const {
    const Command& command = commands_[primitive.command];
    if (command.callback) return {};  // draws nothing of its own (e.g. a render-state reset)
    ImVec2 low(FLT_MAX, FLT_MAX), high(-FLT_MAX, -FLT_MAX);
    for (unsigned corner = 0; corner < 3; ++corner) {
        const ImVec2 p = vertex(list, command, 3 * primitive.triangle + corner).pos;
        low = ImVec2(std::min(low.x, p.x), std::min(low.y, p.y));
        high = ImVec2(std::max(high.x, p.x), std::max(high.y, p.y));
    }
    const PixelArea box{int(std::floor(low.x - origin_.x)), int(std::floor(low.y - origin_.y)),
                        int(std::ceil(high.x - origin_.x)), int(std::ceil(high.y - origin_.y))};
    return intersect(box, command.scissor);
}

std::vector<PixelArea> DrawDataSnapshot::changedAreas(const List& list,
                                                      const DrawDataSnapshot& before,
                                                      const List& beforeList) const {
    const std::vector<Primitive> now = primitives(list);
    const std::vector<Primitive> then = before.primitives(beforeList);
    const std::vector<DiffHunk> hunks =
        differingStretches(then.size(), now.size(), [&](std::size_t i, std::size_t j) {
            return samePrimitive(list, now[j], before, beforeList, then[i]);
        });
    // Each hunk's pixels, before and after.
    std::vector<PixelArea> areas;
    for (const DiffHunk& hunk : hunks) {
        PixelArea area;
        for (std::size_t i = hunk.oldBegin; i < hunk.oldEnd; ++i)
            area = unite(area, before.primitiveArea(beforeList, then[i]));
        for (std::size_t j = hunk.newBegin; j < hunk.newEnd; ++j)
            area = unite(area, primitiveArea(list, now[j]));
        if (!area.empty()) areas.push_back(area);
    }
    return areas;
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
