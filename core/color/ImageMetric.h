#pragma once
// The two per-pixel image errors matevo computes between renders: CIEDE2000
// (ImageDifference.h) and LDR-ꟻLIP (Flip.h), and their names on the command line.
#include <array>
#include <optional>
#include <string_view>

#include "common/Choice.h"

namespace matevo {

enum class ImageMetric { DeltaE00, Flip };

// The image metrics by name: --heatmap, compare --metric, the editor's heatmap choice.
inline constexpr std::array<Choice<ImageMetric>, 2> kImageMetrics{{
    {ImageMetric::DeltaE00, "de00", "ΔE00"},
    {ImageMetric::Flip, "flip", "FLIP"},
}};

// "de00" or "flip".
std::string_view toString(ImageMetric metric);
std::optional<ImageMetric> parseImageMetric(std::string_view name);

}  // namespace matevo
