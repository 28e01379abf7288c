#pragma once
// What the inspector says about the pixel under the pointer: the ΔE00 there between target and
// candidate (and the ꟻLIP error while the heatmap shows it) and both colours, read from the host
// copies of the tile-size renders the maps were computed from, so the numbers are the grid's own.
#include <array>
#include <optional>

#include "color/ColorSpaces.h"
#include "color/Flip.h"
#include "color/ImageDifference.h"
#include "common/Image.h"

namespace matevo::ui {

struct PixelColour {
    bool covered = false;       // the sphere covers the pixel (else it is background)
    std::array<int, 3> srgb{};  // 0-255, as displayed
    Lab lab;                    // what ΔE00 is computed from
};

struct PixelReadout {
    int x = 0;
    int y = 0;                     // in the tile-size renders, top left first
    std::optional<double> deltaE;  // where both renders cover the pixel
    std::optional<double> flip;    // the same pixels, when a ꟻLIP map is given
    PixelColour target;
    PixelColour candidate;
};

// The pixel at (u, v) in [0, 1)² of the shown image; nothing when an image is missing or the
// images and maps differ in size. `flip` may be null.
std::optional<PixelReadout> readPixel(const Image* target, const Image* candidate,
                                      const ErrorMap* deltaE, float u, float v,
                                      const ErrorMap* flip = nullptr);

}  // namespace matevo::ui
