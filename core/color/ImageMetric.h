#pragma once
// The two per-pixel image errors matevo computes between renders: CIEDE2000
// (ImageDifference.h) and LDR-ꟻLIP (Flip.h), and their names on the command line.
#include <optional>
#include <string_view>

namespace matevo {

enum class ImageMetric { DeltaE00, Flip };

// "de00" or "flip".
std::string_view toString(ImageMetric metric);
std::optional<ImageMetric> parseImageMetric(std::string_view name);

}  // namespace matevo
