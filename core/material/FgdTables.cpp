#include "material/FgdTables.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <utility>

namespace matevo {

namespace {

// Blend of two neighbouring nodes along a geometric axis: a^(1 - w) b^w, exact for the power
// law (ln eta)^2 that Fresnel energy follows on the eta axis's geometric steps; linear where a
// node holds 0.
double blendGeometric(double a, double b, double weight) {
    if (a <= 0.0 || b <= 0.0) return a + weight * (b - a);
    return a * std::pow(b / a, weight);
}

// Multilinear interpolation over D axes; axes are listed slowest first, as the data is laid out.
// Along axis `geometricAxis` (none when it is D) neighbours are blended geometrically.
template <std::size_t D>
double interpolate(const std::vector<float>& data, const std::array<const TableAxis*, D>& axes,
                   const std::array<double, D>& values, std::size_t geometricAxis = D) {
    std::array<std::size_t, D> lower{};
    std::array<double, D> weight{};
    std::size_t geometricStride = 1;
    for (std::size_t d = 0; d < D; ++d) {
        const double position = axes[d]->nodeCoordinate(values[d]);
        const int node = std::min(int(position), axes[d]->count - 2);
        lower[d] = std::size_t(node);
        weight[d] = position - node;
        if (d > geometricAxis) geometricStride *= std::size_t(axes[d]->count);
    }
    double sum = 0.0;
    for (std::size_t corner = 0; corner < (std::size_t(1) << D); ++corner) {
        std::size_t index = 0;
        double cornerWeight = 1.0;
        bool pairedWithLower = false;  // the geometric axis's upper node, taken with its lower
        for (std::size_t d = 0; d < D; ++d) {
            const bool upper = (corner >> (D - 1 - d)) & 1u;
            index = index * std::size_t(axes[d]->count) + lower[d] + (upper ? 1 : 0);
            if (d == geometricAxis) {
                pairedWithLower = upper;
                continue;
            }
            cornerWeight *= upper ? weight[d] : 1.0 - weight[d];
        }
        if (pairedWithLower || cornerWeight <= 0.0) continue;
        const double value =
            geometricAxis < D
                ? blendGeometric(data[index], data[index + geometricStride], weight[geometricAxis])
                : double(data[index]);
        sum += cornerWeight * value;
    }
    return sum;
}

// The variable in which an axis is uniform, and back.
double toAxisVariable(AxisSpacing spacing, double x) {
    if (spacing == AxisSpacing::Uniform) return x;
    return std::asinh(std::log(std::max(x, 1e-300)) / kIndexAxisWidth);
}

double fromAxisVariable(AxisSpacing spacing, double s) {
    if (spacing == AxisSpacing::Uniform) return s;
    return std::exp(kIndexAxisWidth * std::sinh(s));
}

}  // namespace

double TableAxis::nodeCoordinate(double x) const {
    const double low = toAxisVariable(spacing, min);
    const double high = toAxisVariable(spacing, max);
    const double position = (toAxisVariable(spacing, x) - low) / (high - low) * double(count - 1);
    return std::clamp(position, 0.0, double(count - 1));
}

double TableAxis::nodeValue(int k) const {
    if (k == 0) return min;  // exact ends, whatever the spacing's rounding
    if (k == count - 1) return max;
    const double low = toAxisVariable(spacing, min);
    const double high = toAxisVariable(spacing, max);
    return fromAxisVariable(spacing, low + (high - low) * double(k) / (count - 1));
}

FgdTables::FgdTables(TableGrid grid, std::vector<float> fgd, std::vector<float> tir)
    : grid_(grid), fgd_(std::move(fgd)), tir_(std::move(tir)) {
    assert(fgd_.size() == grid_.fgdSize() && tir_.size() == grid_.tirSize());
}

double FgdTables::reflectance(double cosTheta, double alpha, double eta, double kappa) const {
    // Geometric blending suits the geometric steps of the index spacing only.
    constexpr std::size_t kEtaAxis = 2, kNoAxis = 4;
    const bool geometric = grid_.eta.spacing == AxisSpacing::IndexOfRefraction;
    return interpolate<4>(fgd_, {&grid_.mu, &grid_.alpha, &grid_.eta, &grid_.kappa},
                          {cosTheta, alpha, eta, kappa}, geometric ? kEtaAxis : kNoAxis);
}

double FgdTables::escapeFraction(double cosTheta, double alpha, double eta) const {
    return interpolate<3>(tir_, {&grid_.mu, &grid_.alpha, &grid_.eta}, {cosTheta, alpha, eta});
}

}  // namespace matevo
