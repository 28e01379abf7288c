#pragma once
// Rectangles of framebuffer pixels, and sets of them kept disjoint: the parts of a window that
// a frame redraws. Overlapping parts would be drawn twice, and blending twice over the same
// pixel changes it.
#include <span>
#include <vector>

namespace matevo::ui {

// [x0, x1) × [y0, y1).
struct PixelArea {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool operator==(const PixelArea&) const = default;
};

PixelArea intersect(const PixelArea& a, const PixelArea& b);  // empty when they do not meet
PixelArea unite(const PixelArea& a, const PixelArea& b);      // the smallest area holding both

// Adds the pixels of `area` that `areas` (disjoint) does not hold yet, as disjoint rectangles.
// Past `kMaxDisjointAreas` rectangles, the nearest ones are merged into the rectangles holding
// them (those that add the fewest pixels first), so the set may cover a few more pixels.
inline constexpr std::size_t kMaxDisjointAreas = 24;
void addDisjoint(std::vector<PixelArea>& areas, const PixelArea& area);

}  // namespace matevo::ui
