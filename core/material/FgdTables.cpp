#include "material/FgdTables.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <utility>

namespace matevo {

namespace {

// Multilinear interpolation over D axes; axes are listed slowest first, as the data is laid out.
template <std::size_t D>
double interpolate(const std::vector<float>& data, const std::array<const TableAxis*, D>& axes,
                   const std::array<double, D>& values) {
    std::array<std::size_t, D> lower{};
    std::array<double, D> weight{};
    for (std::size_t d = 0; d < D; ++d) {
        const double position = axes[d]->nodeCoordinate(values[d]);
        const int node = std::min(int(position), axes[d]->count - 2);
        lower[d] = std::size_t(node);
        weight[d] = position - node;
    }
    double sum = 0.0;
    for (std::size_t corner = 0; corner < (std::size_t(1) << D); ++corner) {
        std::size_t index = 0;
        double cornerWeight = 1.0;
        for (std::size_t d = 0; d < D; ++d) {
            const bool upper = (corner >> (D - 1 - d)) & 1u;
            index = index * std::size_t(axes[d]->count) + lower[d] + (upper ? 1 : 0);
            cornerWeight *= upper ? weight[d] : 1.0 - weight[d];
        }
        if (cornerWeight > 0.0) sum += cornerWeight * double(data[index]);
    }
    return sum;
}

}  // namespace

double TableAxis::nodeCoordinate(double x) const {
    const double position = (x - min) / (max - min) * double(count - 1);
    return std::clamp(position, 0.0, double(count - 1));
}

double TableAxis::nodeValue(int k) const { return min + (max - min) * double(k) / (count - 1); }

FgdTables::FgdTables(TableGrid grid, std::vector<float> fgd, std::vector<float> tir)
    : grid_(grid), fgd_(std::move(fgd)), tir_(std::move(tir)) {
    assert(fgd_.size() == grid_.fgdSize() && tir_.size() == grid_.tirSize());
}

double FgdTables::reflectance(double cosTheta, double alpha, double eta, double kappa) const {
    return interpolate<4>(fgd_, {&grid_.mu, &grid_.alpha, &grid_.eta, &grid_.kappa},
                          {cosTheta, alpha, eta, kappa});
}

double FgdTables::escapeFraction(double cosTheta, double alpha, double eta) const {
    return interpolate<3>(tir_, {&grid_.mu, &grid_.alpha, &grid_.eta}, {cosTheta, alpha, eta});
}

}  // namespace matevo
