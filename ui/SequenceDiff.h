#pragma once
// Where two sequences differ: their elements paired up in order where equal, and the stretches
// left unpaired. A frame's draw list is such a sequence of triangles, and most of it is the
// same as in the frame before (a changed number in a label shifts the triangles after it in the
// buffer, but not on screen): only the stretches that differ need drawing again.
#include <cstddef>
#include <functional>
#include <vector>

namespace matevo::ui {

// Elements [oldBegin, oldEnd) of the old sequence stand where [newBegin, newEnd) of the new one
// do; either may be empty (an insertion or a removal).
struct DiffHunk {
    std::size_t oldBegin = 0, oldEnd = 0, newBegin = 0, newEnd = 0;
    bool operator==(const DiffHunk&) const = default;
};

// The hunks between a sequence of `oldSize` elements and one of `newSize`, in order; between
// them, elements are pairwise equal (`equal(i, j)`: old element i equals new element j). Not
// the shortest such list: after a difference the search for where the sequences agree again
// looks `window` elements ahead in each and wants `anchor` equal elements in a row; past that,
// the rest up to the common tail is one hunk. Cost: linear in the common parts, at most about
// window² comparisons per hunk.
std::vector<DiffHunk> differingStretches(std::size_t oldSize, std::size_t newSize,
                                         const std::function<bool(std::size_t, std::size_t)>& equal,
                                         std::size_t window = 64, std::size_t anchor = 2);

}  // namespace matevo::ui
