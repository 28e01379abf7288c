#include "SequenceDiff.h"

#include <algorithm>

namespace matevo::ui {

std::vector<DiffHunk> differingStretches(std::size_t oldSize, std::size_t newSize,
                                         const std::function<bool(std::size_t, std::size_t)>& equal,
                                         std::size_t window, std::size_t anchor) {
    // `anchor` equal pairs from (i, j) on, or equal pairs up to the end of both sequences.
    const auto agreeFrom = [&](std::size_t i, std::size_t j) {
        for (std::size_t k = 0; k < anchor; ++k, ++i, ++j) {
            if (i == oldSize || j == newSize) return i == oldSize && j == newSize;
            if (!equal(i, j)) return false;
        }
        return true;
    };
    std::vector<DiffHunk> hunks;
    std::size_t i = 0, j = 0;
    while (i < oldSize && j < newSize) {
        if (equal(i, j)) {
            ++i, ++j;
            continue;
        }
        // The nearest place where they agree again: skip `skipOld` + `skipNew` elements, fewest
        // first.
        bool found = false;
        for (std::size_t skipped = 1; skipped <= 2 * window && !found; ++skipped) {
            const std::size_t fewest = skipped > window ? skipped - window : 0;
            for (std::size_t skipOld = fewest; skipOld <= std::min(skipped, window); ++skipOld) {
                const std::size_t skipNew = skipped - skipOld;
                if (i + skipOld > oldSize || j + skipNew > newSize) continue;
                if (!agreeFrom(i + skipOld, j + skipNew)) continue;
                hunks.push_back({i, i + skipOld, j, j + skipNew});
                i += skipOld;
                j += skipNew;
                found = true;
                break;
            }
        }
        if (!found) break;
    }
    // The rest: what the sequences end with in common, and one hunk before it.
    std::size_t oldEnd = oldSize, newEnd = newSize;
    while (oldEnd > i && newEnd > j && equal(oldEnd - 1, newEnd - 1)) --oldEnd, --newEnd;
    if (i < oldEnd || j < newEnd) hunks.push_back({i, oldEnd, j, newEnd});
    return hunks;
}

}  // namespace matevo::ui
