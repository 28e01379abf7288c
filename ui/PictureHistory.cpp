#include "PictureHistory.h"

namespace matevo::ui {

void PictureHistory::reset(std::size_t images, PixelArea whole) {
    whole_ = whole;
    holds_.assign(images, 0);
    changes_.clear();
}

void PictureHistory::forget() { holds_.assign(holds_.size(), 0); }

std::vector<PixelArea> PictureHistory::areasToDraw(
    std::size_t image, const std::optional<std::vector<PixelArea>>& changed) const {
    const std::uint64_t holds = image < holds_.size() ? holds_[image] : 0;
    if (holds == 0 || !changed) return {whole_};
    // The changes of the frames drawn since the image's picture, then the next frame's.
    std::vector<PixelArea> areas;
    std::uint64_t covered = lastFrame_;
    for (auto change = changes_.rbegin(); change != changes_.rend(); ++change) {
        if (change->frame <= holds) break;
        for (const PixelArea& area : change->areas) addDisjoint(areas, area);
        covered = change->frame - 1;
    }
    if (covered != holds) return {whole_};  // older than the changes kept
    for (const PixelArea& area : *changed) addDisjoint(areas, area);
    // Within the image, whatever size the caller's picture had.
    std::vector<PixelArea> inside;
    for (const PixelArea& area : areas)
        if (const PixelArea part = intersect(area, whole_); !part.empty()) inside.push_back(part);
    return inside;
}

void PictureHistory::drawn(std::size_t image,
                           const std::optional<std::vector<PixelArea>>& changed) {
    ++lastFrame_;
    if (image < holds_.size()) holds_[image] = lastFrame_;
    changes_.push_back({lastFrame_, changed.value_or(std::vector<PixelArea>{whole_})});
    // An image older than the others' frames is drawn whole anyway.
    while (changes_.size() > holds_.size()) changes_.pop_front();
}

}  // namespace matevo::ui
