#pragma once
// Which pixels of a swapchain image must be drawn for it to show the next frame. An image keeps
// the picture it was last drawn with; the frames drawn since (into other images) changed some
// areas, and the next frame changes more: with images that rotate, the image needs the union of
// those changes. (On lavapipe under Xvfb the same image comes back every frame, and only the
// next frame's changes are drawn.) No Vulkan here: the window renderer asks it per frame.
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "PixelArea.h"

namespace matevo::ui {

class PictureHistory {
public:
    // A swapchain of `images` images of size `whole`, whose pictures are not known yet.
    void reset(std::size_t images, PixelArea whole);
    // What to draw into image `image` for the next frame, as disjoint areas within the image;
    // `changed`: where the next frame's picture differs from the last frame drawn (nullopt:
    // anywhere).
    std::vector<PixelArea> areasToDraw(std::size_t image,
                                       const std::optional<std::vector<PixelArea>>& changed) const;
    // The next frame (`changed` as above) was drawn into image `image`.
    void drawn(std::size_t image, const std::optional<std::vector<PixelArea>>& changed);
    // No image's picture is known any more (e.g. the window was uncovered).
    void forget();

private:
    struct Change {
        std::uint64_t frame;
        std::vector<PixelArea> areas;  // where it differs from the frame before
    };
    PixelArea whole_;
    std::vector<std::uint64_t> holds_;  // per image, the frame whose picture it holds; 0: none
    std::uint64_t lastFrame_ = 0;       // frames drawn so far
    std::deque<Change> changes_;        // of the last frames, newest last
};

}  // namespace matevo::ui
