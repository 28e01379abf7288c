#pragma once
// The FGD and TIR tables and their lookup — the only place that interpolates them.
//
// Grid (endpoint-inclusive, docs/bsdf.md §3.2): axis a with N nodes spans [min, max]. A
// uniform axis puts node k at min + k (max - min) / (N - 1); the eta axis is uniform in
// s(eta) = asinh(ln(eta) / w) instead (AxisSpacing::IndexOfRefraction), which makes its nodes
// geometric in |ln eta| away from 1 and evenly w-spaced within about w of it: Fresnel energy
// near eta = 1 grows like (eta - 1)^2, and only geometric steps keep its interpolation error
// small in relative terms (docs/belcour-decisions.md). Ranges: cosine mu in [0, 1], GGX
// roughness alpha in [0, 1], relative eta in [0.05, 6], relative kappa in [0, 4]. The nodes at
// 0 of mu and alpha were evaluated at 1e-4 (see FgdIntegrals.h). Lookups clamp into range and
// interpolate multilinearly (in the axis variable) between the 2^D surrounding nodes, except
// that FGD blends its two eta neighbours geometrically (a^(1-w) b^w) on the index spacing: on
// its geometric steps that is exact for Fresnel energy's power law near eta = 1.
//
// Memory layout (flat float32; only the CPU reads it: the GPU gets the lobe tables built from
// it, so no shader has to repeat the eta spacing or the geometric blend):
//   FGD: index = k + Nkappa * (e + Neta * (a + Nalpha * m))   (mu slowest, kappa fastest)
//   TIR: index = e + Neta * (a + Nalpha * m)                  (mu slowest, eta fastest)
#include <vector>

#include "material/InterfaceAlbedo.h"

namespace matevo {

// How an axis places its nodes between min and max.
enum class AxisSpacing : int {
    Uniform = 0,            // evenly in x
    IndexOfRefraction = 1,  // evenly in asinh(ln(x) / kIndexAxisWidth); needs min > 0
};

// Half-width, in ln(eta), of the region around eta = 1 where the index axis is near-uniform.
constexpr double kIndexAxisWidth = 0.01;

struct TableAxis {
    int count = 2;
    double min = 0.0;
    double max = 1.0;
    AxisSpacing spacing = AxisSpacing::Uniform;

    // The continuous node coordinate of x in [0, count - 1] (clamped).
    double nodeCoordinate(double x) const;
    // The value at node k.
    double nodeValue(int k) const;

    bool operator==(const TableAxis&) const = default;
};

struct TableGrid {
    // 33 nodes: steps of 1/32 and 1/8 put the reference values of docs/bsdf.md §8
    // (mu = .5, alpha = .5, kappa = 1) on nodes. eta: 48 nodes over [0.05, 6] step |ln eta| by
    // about 30 % away from 1 (conductor bases reach 0.05, dielectric ones 6). The measured
    // interpolation error behind both choices is in docs/belcour-decisions.md.
    TableAxis mu{33, 0.0, 1.0};
    TableAxis alpha{33, 0.0, 1.0};
    TableAxis eta{48, 0.05, 6.0, AxisSpacing::IndexOfRefraction};
    TableAxis kappa{33, 0.0, 4.0};

    std::size_t fgdSize() const {
        return std::size_t(mu.count) * alpha.count * eta.count * kappa.count;
    }
    std::size_t tirSize() const { return std::size_t(mu.count) * alpha.count * eta.count; }

    bool operator==(const TableGrid&) const = default;
};

class FgdTables final : public InterfaceAlbedo {
public:
    // Sizes must match grid.fgdSize() and grid.tirSize().
    FgdTables(TableGrid grid, std::vector<float> fgd, std::vector<float> tir);

    double reflectance(double cosTheta, double alpha, double eta, double kappa) const override;
    double escapeFraction(double cosTheta, double alpha, double eta) const override;

    const TableGrid& grid() const { return grid_; }
    const std::vector<float>& fgdData() const { return fgd_; }
    const std::vector<float>& tirData() const { return tir_; }

private:
    TableGrid grid_;
    std::vector<float> fgd_;
    std::vector<float> tir_;
};

}  // namespace matevo
