// What a swapchain image must redraw: the changes of every frame drawn since its own picture
// (into the other images) and the next frame's. Checked against a simulation of the images'
// pixels, with images that rotate as a compositor may hand them back (on lavapipe under Xvfb
// the same image always comes back, so the window's end-to-end test covers only that case).
#include "PictureHistory.h"

#include <random>

#include <gtest/gtest.h>

namespace matevo::testing {
namespace {

using ui::PictureHistory;
using ui::PixelArea;

constexpr PixelArea kWhole{0, 0, 64, 48};

bool holds(const std::vector<PixelArea>& areas, int x, int y) {
    for (const PixelArea& area : areas)
        if (x >= area.x0 && x < area.x1 && y >= area.y0 && y < area.y1) return true;
    return false;
}

TEST(PictureHistory, UnknownPicturesAndUnknownChangesAreDrawnWhole) {
    PictureHistory history;
    history.reset(3, kWhole);
    const std::vector<PixelArea> whole{kWhole};
    const std::vector<PixelArea> change{{1, 1, 5, 5}};
    EXPECT_EQ(history.areasToDraw(0, change), whole);  // nothing drawn into it yet
    history.drawn(0, std::nullopt);
    EXPECT_EQ(history.areasToDraw(0, std::nullopt), whole);
    EXPECT_EQ(history.areasToDraw(0, change), change);
    history.forget();
    EXPECT_EQ(history.areasToDraw(0, change), whole);
}

TEST(PictureHistory, ARotatedImageRedrawsTheChangesOfTheFramesDrawnSinceItsOwn) {
    PictureHistory history;
    history.reset(3, kWhole);
    for (std::size_t image = 0; image < 3; ++image) history.drawn(image, std::nullopt);
    const PixelArea a{0, 0, 4, 4}, b{10, 10, 14, 14}, c{20, 20, 24, 24}, d{30, 30, 34, 34};
    history.drawn(0, std::vector<PixelArea>{a});  // image 0 now holds frame 4
    history.drawn(1, std::vector<PixelArea>{b});  // image 1: frame 5
    history.drawn(2, std::vector<PixelArea>{c});  // image 2: frame 6
    // Image 0 misses frames 5 and 6, then shows frame 7.
    const auto areas = history.areasToDraw(0, std::vector<PixelArea>{d});
    EXPECT_EQ(areas.size(), 3u);
    for (const PixelArea& area : {b, c, d}) EXPECT_TRUE(holds(areas, area.x0, area.y0));
    EXPECT_FALSE(holds(areas, a.x0, a.y0)) << "frame 4's change is already in image 0";
    // The same image again: only the new frame's change.
    EXPECT_EQ(history.areasToDraw(2, std::vector<PixelArea>{d}), std::vector<PixelArea>{d});
}

TEST(PictureHistory, AnImageOlderThanTheChangesKeptIsDrawnWhole) {
    PictureHistory history;
    history.reset(2, kWhole);
    history.drawn(0, std::nullopt);
    for (int frame = 0; frame < 3; ++frame) history.drawn(1, std::vector<PixelArea>{{0, 0, 2, 2}});
    EXPECT_EQ(history.areasToDraw(0, std::vector<PixelArea>{{5, 5, 6, 6}}),
              std::vector<PixelArea>{kWhole});
}

// Each frame changes a few random rectangles of the picture and is drawn into a random image,
// only within the areas the history names: every image must then show the frame's picture.
TEST(PictureHistory, DrawingOnlyTheNamedAreasKeepsEveryImageRightWhateverTheOrder) {
    std::mt19937 random(7);
    for (std::size_t imageCount : {1u, 2u, 3u, 4u}) {
        PictureHistory history;
        history.reset(imageCount, kWhole);
        const std::size_t pixels = std::size_t(kWhole.x1 * kWhole.y1);
        std::vector<int> picture(pixels, 0);  // per pixel, the frame that last changed it
        std::vector<std::vector<int>> images(imageCount, std::vector<int>(pixels, -1));
        for (int frame = 1; frame <= 300; ++frame) {
            std::vector<PixelArea> changed;
            for (int r = int(random() % 4); r > 0; --r) {
                const int x = int(random() % 56), y = int(random() % 40);  // within the image
                changed.push_back({x, y, x + 1 + int(random() % 8), y + 1 + int(random() % 8)});
            }
            for (const PixelArea& area : changed)
                for (int y = area.y0; y < area.y1; ++y)
                    for (int x = area.x0; x < area.x1; ++x)
                        picture[std::size_t(y * kWhole.x1 + x)] = frame;
            // Mostly in turn, sometimes the same image again or one out of order.
            const std::size_t image =
                random() % 4 == 0 ? random() % imageCount : std::size_t(frame) % imageCount;
            const std::optional<std::vector<PixelArea>> known =
                frame == 1 || random() % 50 == 0 ? std::nullopt : std::optional(changed);
            const std::vector<PixelArea> areas = history.areasToDraw(image, known);
            for (int y = 0; y < kWhole.y1; ++y)
                for (int x = 0; x < kWhole.x1; ++x)
                    if (holds(areas, x, y))
                        images[image][std::size_t(y * kWhole.x1 + x)] =
                            picture[std::size_t(y * kWhole.x1 + x)];
            history.drawn(image, known);
            ASSERT_EQ(images[image], picture)
                << imageCount << " images, frame " << frame << " into image " << image;
        }
    }
}

}  // namespace
}  // namespace matevo::testing
