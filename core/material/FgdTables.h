#pragma once
// The FGD and TIR tables and their lookup — the only place that interpolates them.
//
// Grid (endpoint-inclusive, docs/bsdf.md §3.2): axis a with N nodes spans [min, max];
// node k sits at min + k (max - min) / (N - 1). Ranges: cosine mu in [0, 1], GGX roughness
// alpha in [0, 1], relative eta in [0, 4], relative kappa in [0, 4]. The nodes at 0 of mu,
// alpha and eta were evaluated at 1e-4 (see FgdIntegrals.h). Lookups clamp into range and
// interpolate multilinearly between the 2^D surrounding nodes.
//
// Memory layout (flat float32, uploadable as is):
//   FGD: index = k + Nkappa * (e + Neta * (a + Nalpha * m))   (mu slowest, kappa fastest)
//        as a 3D texture: width Nkappa, height Neta, depth Nalpha * Nmu. Sample it with two
//        trilinear fetches, one in the mu slab m and one in m + 1 (depth coordinate clamped to
//        the texel centres of that slab, so alpha never blends across slabs), then mix by the
//        mu weight.
//   TIR: index = e + Neta * (a + Nalpha * m)                  (mu slowest, eta fastest)
//        as a 3D texture: width Neta, height Nalpha, depth Nmu; one trilinear fetch.
//   Texel centre of node k on an axis of N nodes: (k + 0.5) / N in normalised coordinates.
#include <vector>

#include "material/InterfaceAlbedo.h"

namespace matevo {

struct TableAxis {
    int count = 2;
    double min = 0.0;
    double max = 1.0;

    // The continuous node coordinate of x in [0, count - 1] (clamped).
    double nodeCoordinate(double x) const;
    // The value at node k.
    double nodeValue(int k) const;

    bool operator==(const TableAxis&) const = default;
};

struct TableGrid {
    // 33 nodes: steps of 1/32 and 1/8 put the reference values of docs/bsdf.md §8
    // (mu = .5, alpha = .5, eta = 1.5, kappa = 1) on nodes; docs/belcour-decisions.md has the
    // measured interpolation error behind the choice.
    TableAxis mu{33, 0.0, 1.0};
    TableAxis alpha{33, 0.0, 1.0};
    TableAxis eta{33, 0.0, 4.0};
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
