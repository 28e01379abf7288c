#pragma once
// How far from the target a variant should be: a band [low, high] of mean ΔE00 between the
// variant's render and the target's. Inside the band the objective is met; outside, the
// distance to the nearer edge says by how much it is missed.
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace matevo {

struct DeltaEBand {
    double low = 2;
    double high = 10;

    bool contains(double deltaE) const { return deltaE >= low && deltaE <= high; }
    // 0 inside, else the distance to the nearer edge.
    double violation(double deltaE) const {
        return deltaE < low ? low - deltaE : deltaE > high ? deltaE - high : 0.0;
    }
    double centre() const { return 0.5 * (low + high); }
    // The band shrunk by margin at each end (never past its centre).
    DeltaEBand inset(double margin) const;

    bool operator==(const DeltaEBand&) const = default;
};

// nullopt for a usable band (finite, 0 <= low <= high), else why not.
std::optional<std::string> validateBand(const DeltaEBand& band);

// The paper's readings of ΔE00 (Bernardi et al. 2020, §5) as one-click choices.
struct NamedBand {
    std::string_view label;
    DeltaEBand band;
};
inline constexpr std::array<NamedBand, 3> kPaperBands = {{
    {"<= 1 not perceptible", {0.0, 1.0}},
    {"1-2 close observation", {1.0, 2.0}},
    {"2-10 at a glance", {2.0, 10.0}},
}};

// "2-5" for reports and messages.
std::string describe(const DeltaEBand& band);

}  // namespace matevo
