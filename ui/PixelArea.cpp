#include "PixelArea.h"

#include <algorithm>

namespace matevo::ui {

PixelArea intersect(const PixelArea& a, const PixelArea& b) {
    const PixelArea inside{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1),
                           std::min(a.y1, b.y1)};
    return inside.empty() ? PixelArea{} : inside;
}

PixelArea unite(const PixelArea& a, const PixelArea& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

namespace {

long long pixels(const PixelArea& area) {
    return area.empty() ? 0 : (long long)(area.x1 - area.x0) * (area.y1 - area.y0);
}

// Replaces the two areas whose enclosing rectangle adds the fewest pixels by that rectangle,
// grown over any other area it meets (so the set stays disjoint): one area fewer at least.
void mergeClosestPair(std::vector<PixelArea>& areas) {
    std::size_t first = 0, second = 1;
    long long leastAdded = -1;
    for (std::size_t i = 0; i < areas.size(); ++i)
        for (std::size_t j = i + 1; j < areas.size(); ++j) {
            const long long added =
                pixels(unite(areas[i], areas[j])) - pixels(areas[i]) - pixels(areas[j]);
            if (leastAdded < 0 || added < leastAdded) {
                leastAdded = added;
                first = i;
                second = j;
            }
        }
    PixelArea merged = unite(areas[first], areas[second]);
    areas.erase(areas.begin() + std::ptrdiff_t(second));
    areas.erase(areas.begin() + std::ptrdiff_t(first));
    for (bool grew = true; grew;) {
        grew = false;
        for (std::size_t i = 0; i < areas.size(); ++i) {
            if (intersect(areas[i], merged).empty()) continue;
            merged = unite(merged, areas[i]);
            areas.erase(areas.begin() + std::ptrdiff_t(i));
            grew = true;
            break;
        }
    }
    areas.push_back(merged);
}

}  // namespace

void addDisjoint(std::vector<PixelArea>& areas, const PixelArea& area) {
    // What is left of `area` once each held rectangle is taken out: at most four strips (above,
    // below, left, right of the held one) per piece.
    std::vector<PixelArea> pieces;
    if (!area.empty()) pieces.push_back(area);
    for (const PixelArea& held : areas) {
        std::vector<PixelArea> left;
        for (const PixelArea& piece : pieces) {
            const PixelArea overlap = intersect(piece, held);
            if (overlap.empty()) {
                left.push_back(piece);
                continue;
            }
            const PixelArea strips[4] = {{piece.x0, piece.y0, piece.x1, overlap.y0},
                                         {piece.x0, overlap.y1, piece.x1, piece.y1},
                                         {piece.x0, overlap.y0, overlap.x0, overlap.y1},
                                         {overlap.x1, overlap.y0, piece.x1, overlap.y1}};
            for (const PixelArea& strip : strips)
                if (!strip.empty()) left.push_back(strip);
        }
        pieces = std::move(left);
    }
    areas.insert(areas.end(), pieces.begin(), pieces.end());
    while (areas.size() > kMaxDisjointAreas) mergeClosestPair(areas);
}

}  // namespace matevo::ui
