#pragma once
// The paper's reading of ΔE00 values (Bernardi et al. 2020, §5), for discrete legends and
// histograms. Each band holds the values above its lower edge up to and including its upper
// edge: [0, 1], (1, 2], (2, 10], (10, 49], (49, ∞). Negative values fall in the first band and
// NaN in the last.
#include <array>
#include <string_view>

namespace matevo {

enum class PerceptualBand {
    kNotPerceptible,           // ≤ 1
    kCloseObservation,         // 1 – 2: perceptible through close observation
    kAtAGlance,                // 2 – 10: perceptible at a glance
    kMoreSimilarThanOpposite,  // 10 – 49
    kOpposite,                 // > 49
};

inline constexpr int kPerceptualBandCount = 5;
inline constexpr std::array<PerceptualBand, kPerceptualBandCount> kPerceptualBands = {
    PerceptualBand::kNotPerceptible, PerceptualBand::kCloseObservation, PerceptualBand::kAtAGlance,
    PerceptualBand::kMoreSimilarThanOpposite, PerceptualBand::kOpposite};

PerceptualBand classifyDeltaE(double deltaE);

// The inclusive upper edge (infinity for the last band).
double bandUpperEdge(PerceptualBand band);
// Plain-ASCII texts for legends (the default UI font has no ≤): "<= 1", "1-2", ... "> 49".
std::string_view bandRangeLabel(PerceptualBand band);
// "not perceptible", "perceptible through close observation", ...
std::string_view bandDescription(PerceptualBand band);
// sRGB-encoded, ready for display: five evenly spaced samples of the heatmap's viridis, so the
// legend reads low-to-high like the heatmap and stays legible to colour-blind viewers.
std::array<float, 3> bandColorSrgb(PerceptualBand band);

}  // namespace matevo
