#pragma once
// What a frame's ImGui draw data puts on screen, kept as plain bytes: the display rectangle,
// every draw list's vertices, indices and commands (clip rectangle, texture, ranges, callback),
// and whatever else the caller says changes the picture (e.g. a heatmap range applied by the
// renderer). Two equal snapshots draw the same pixels as long as each texture id keeps its
// contents. On lavapipe every pixel drawn costs: a frame equal to the one on screen need not
// be drawn at all, and one that differs only in some windows need only redraw their area.
#include <cstddef>
#include <span>
#include <vector>

#include <imgui.h>

namespace matevo::ui {

// A rectangle of framebuffer pixels, [x0, x1) × [y0, y1).
struct PixelArea {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool operator==(const PixelArea&) const = default;
};

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
    // The framebuffer pixels that may differ between `before`'s picture and this one: the
    // area of every draw list that changed, in the old and the new frame (a list's pixels lie
    // within its commands' clip rectangles); the whole framebuffer when the display, the
    // extra bytes or the framebuffer scale changed, or `before` is empty.
    PixelArea changedSince(const DrawDataSnapshot& before) const;
    PixelArea whole() const { return whole_; }

private:
    struct List {
        std::size_t begin, end;  // its bytes
        PixelArea area;          // where it draws
    };
    template <typename T>
    void append(const T& value);
    void appendBytes(const void* data, std::size_t size);

    std::vector<std::byte> bytes_;  // reused: a frame's snapshot is some 100 kB
    std::size_t headerEnd_ = 0;     // the display and the extra bytes
    std::vector<List> lists_;
    PixelArea whole_;
    bool unitScale_ = false;  // areas are exact only at one framebuffer pixel per display unit
};

// The smallest area holding both.
PixelArea unite(const PixelArea& a, const PixelArea& b);

// Restricts every command of `drawData` to `area`: its clip rectangle becomes the part of the
// scissor the Vulkan backends derive from it (whole pixels) that lies within `area`, empty when
// none does. The commands then draw exactly the pixels of `area` they drew before. Needs one
// framebuffer pixel per display unit (changedSince returns the whole framebuffer otherwise).
void clipDrawData(ImDrawData& drawData, const PixelArea& area);

}  // namespace matevo::ui
