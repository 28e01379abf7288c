#pragma once
// What a frame's ImGui draw data puts on screen, kept as plain bytes: the display rectangle,
// every draw list's vertices, indices and commands (clip rectangle, texture, ranges, callback),
// and whatever else the caller says changes the picture (e.g. a heatmap range applied by the
// renderer). Two equal snapshots draw the same pixels as long as each texture id keeps its
// contents. On lavapipe every pixel drawn costs: a frame equal to the one on screen need not
// be drawn at all, and one that differs only in some triangles need only redraw their area.
#include <cstddef>
#include <span>
#include <vector>

#include <imgui.h>

#include "PixelArea.h"

namespace matevo::ui {

class DrawDataSnapshot {
public:
    // Replaces the snapshot by `drawData` (after ImGui::Render) and `extra`.
    void capture(const ImDrawData& drawData, std::span<const std::byte> extra = {});
    // Forgets what was captured: equal to no other snapshot until the next capture.
    void clear();
    bool empty() const { return bytes_.empty(); }
    bool operator==(const DrawDataSnapshot& other) const {
        return !bytes_.empty() && bytes_ == other.bytes_;
    }
    // The framebuffer pixels that may differ between `before`'s picture and this one, as
    // disjoint rectangles (none: nothing changed): in each draw list, where the triangles that
    // differ lie in the old and the new frame (within their commands' scissors; the triangles
    // both frames draw in the same order need no redraw, wherever they sit in the buffers); a
    // list that only one frame has, where it draws; the whole framebuffer when the display, the
    // extra bytes or the framebuffer scale changed, or `before` is empty.
    std::vector<PixelArea> changedSince(const DrawDataSnapshot& before) const;
    PixelArea whole() const { return whole_; }

private:
    struct Command {
        ImVec4 clipRect;
        ImTextureID texture;
        ImDrawCallback callback;
        void* callbackData;
        unsigned vertexOffset, indexOffset, elementCount;
        PixelArea scissor;
    };
    struct List {
        std::size_t begin, end;                  // its bytes
        PixelArea area;                          // where it draws
        std::size_t firstCommand, commandCount;  // in commands_
        std::size_t vertices, indices;           // where its buffers start in bytes_
    };
    // A triangle of a list (or a callback, which draws nothing itself), in drawing order.
    struct Primitive {
        std::size_t command;  // in commands_
        unsigned triangle;    // within the command
    };
    template <typename T>
    void append(const T& value);
    void appendBytes(const void* data, std::size_t size);
    std::vector<Primitive> primitives(const List& list) const;
    ImDrawVert vertex(const List& list, const Command& command, unsigned element) const;
    bool samePrimitive(const List& list, const Primitive& primitive, const DrawDataSnapshot& other,
                       const List& otherList, const Primitive& otherPrimitive) const;
    PixelArea primitiveArea(const List& list, const Primitive& primitive) const;
    // Where the triangles of `list` differ from those of `before`'s `beforeList`.
    std::vector<PixelArea> changedAreas(const List& list, const DrawDataSnapshot& before,
                                        const List& beforeList) const;

    std::vector<std::byte> bytes_;  // reused: a frame's snapshot is some 100 kB
    std::size_t headerEnd_ = 0;     // the display and the extra bytes
    std::vector<List> lists_;
    std::vector<Command> commands_;
    ImVec2 origin_;  // the display position
    PixelArea whole_;
    bool unitScale_ = false;  // areas are exact only at one framebuffer pixel per display unit
};

// Restricts `drawData` to `areas` (disjoint): each command becomes one per area it reaches,
// whose clip rectangle is the part of the command's scissor (whole pixels, as the Vulkan
// backends derive it) within that area. The commands then draw exactly the pixels of `areas`
// they drew before, each once, in the same order. Needs one framebuffer pixel per display unit
// (changedSince returns the whole framebuffer otherwise).
void clipDrawData(ImDrawData& drawData, std::span<const PixelArea> areas);

}  // namespace matevo::ui
