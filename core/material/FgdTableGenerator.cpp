#include "material/FgdTableGenerator.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "common/ParallelFor.h"
#include "material/FgdIntegrals.h"
#include "material/Fresnel.h"

namespace matevo {

namespace {

// Sparse tent-weighted histogram of a value in [0, 1] over `intervals` equal intervals.
class TentHistogram {
public:
    explicit TentHistogram(int intervals) : intervals_(intervals), mass_(intervals + 1, 0.0) {}

    void add(double value, double weight) {
        const double position = std::clamp(value, 0.0, 1.0) * intervals_;
        const int lower = std::min(int(position), intervals_ - 1);
        const double upperShare = position - lower;
        mass_[lower] += weight * (1.0 - upperShare);
        mass_[lower + 1] += weight * upperShare;
    }

    // (node, mass) for the non-empty nodes; sharp lobes touch only a few of them.
    std::vector<std::pair<int, double>> nonEmpty() const {
        std::vector<std::pair<int, double>> entries;
        for (int node = 0; node <= intervals_; ++node)
            if (mass_[node] != 0.0) entries.emplace_back(node, mass_[node]);
        return entries;
    }

private:
    int intervals_;
    std::vector<double> mass_;
};

double nodeEta(const TableGrid& grid, int e) {
    return std::max(grid.eta.nodeValue(e), kIntegrationFloor);
}

}  // namespace

FgdTables generateFgdTables(const TableGenerationSettings& settings,
                            const std::function<void(double fraction)>& progress) {
    const TableGrid& grid = settings.grid;
    const int bins = settings.histogramIntervals + 1;
    const int etaKappaCount = grid.eta.count * grid.kappa.count;

    // Fresnel terms at the histogram nodes, shared by every (mu, alpha) node.
    std::vector<double> fresnelAtBins(std::size_t(etaKappaCount) * bins);
    std::vector<double> escapeAtBins(std::size_t(grid.eta.count) * bins);
    std::vector<double> fresnelAverage(etaKappaCount);
    for (int e = 0; e < grid.eta.count; ++e) {
        for (int b = 0; b < bins; ++b) {
            const double cosine = double(b) / settings.histogramIntervals;
            escapeAtBins[std::size_t(e) * bins + b] =
                1.0 - fresnelDielectric(cosine, nodeEta(grid, e));
            for (int k = 0; k < grid.kappa.count; ++k)
                fresnelAtBins[std::size_t(e * grid.kappa.count + k) * bins + b] =
                    fresnelConductor(cosine, nodeEta(grid, e), grid.kappa.nodeValue(k));
        }
        for (int k = 0; k < grid.kappa.count; ++k)
            fresnelAverage[e * grid.kappa.count + k] =
                averageFresnel(nodeEta(grid, e), grid.kappa.nodeValue(k));
    }
    std::vector<double> albedoAverage(grid.alpha.count);
    for (int a = 0; a < grid.alpha.count; ++a)
        albedoAverage[a] = averageMaskingAlbedo(grid.alpha.nodeValue(a));

    std::vector<float> fgd(grid.fgdSize());
    std::vector<float> tir(grid.tirSize());
    const double sampleCount = double(settings.samplesPerAxis) * settings.samplesPerAxis;
    const int cellCount = grid.mu.count * grid.alpha.count;
    auto fillCell = [&](int cell) {
        const int m = cell / grid.alpha.count;
        const int a = cell % grid.alpha.count;
        TentHistogram fresnelCosines(settings.histogramIntervals);
        TentHistogram outgoingCosines(settings.histogramIntervals);
        double weightSum = 0.0;
        forEachReflectionSample(grid.mu.nodeValue(m), grid.alpha.nodeValue(a),
                                settings.samplesPerAxis, [&](const ReflectionSample& s) {
                                    fresnelCosines.add(s.cosIncidentHalf, s.weight);
                                    outgoingCosines.add(s.cosOutgoing, s.weight);
                                    weightSum += s.weight;
                                });
        const double albedo = weightSum / sampleCount;
        const auto dMass = fresnelCosines.nonEmpty();
        const auto outMass = outgoingCosines.nonEmpty();
        for (int e = 0; e < grid.eta.count; ++e) {
            for (int k = 0; k < grid.kappa.count; ++k) {
                const double* fresnel =
                    &fresnelAtBins[std::size_t(e * grid.kappa.count + k) * bins];
                double sum = 0.0;
                for (const auto& [bin, mass] : dMass) sum += mass * fresnel[bin];
                double value = sum / sampleCount;
                if (isConductorKappa(grid.kappa.nodeValue(k)))
                    value = addMultipleScattering(
                        value, albedo, fresnelAverage[e * grid.kappa.count + k], albedoAverage[a]);
                fgd[std::size_t(cell * grid.eta.count + e) * grid.kappa.count + k] = float(value);
            }
            const double* escape = &escapeAtBins[std::size_t(e) * bins];
            double escaping = 0.0;
            for (const auto& [bin, mass] : outMass) escaping += mass * escape[bin];
            tir[std::size_t(cell) * grid.eta.count + e] =
                float(weightSum > 0.0 ? escaping / weightSum : 1.0);
        }
    };
    parallelForChunks(cellCount, fillCell, [&](int done) {
        if (progress) progress(double(done) / cellCount);
    });
    return FgdTables(grid, std::move(fgd), std::move(tir));
}

}  // namespace matevo
