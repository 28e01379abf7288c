#pragma once
// The 12-chromosome genotype of Bernardi et al. (2020) §4.2: two interfaces (eta, alpha), an
// optional participating medium (depth h, sigma_s RGB, sigma_a RGB, Henyey-Greenstein g).
// Indices follow the command-line order of --weights and the JSON schema.
// Beyond the paper, three more genes hold the conductor base's extinction kappa (RGB) for hue
// variety (docs/variants.md): inactive, and 0, unless asked for (KappaGenes::On), so the paper's
// operators leave them alone and the paper's runs are unchanged.
#include <array>
#include <cstddef>
#include <string_view>

namespace matevo {

enum Chromosome : std::size_t {
    kEta1,
    kEta2,
    kAlpha1,
    kAlpha2,
    kDepth,
    kSigmaSR,
    kSigmaSG,
    kSigmaSB,
    kSigmaAR,
    kSigmaAG,
    kSigmaAB,
    kG,
    kKappaR,
    kKappaG,
    kKappaB,
    kChromosomeCount
};

// The paper's genotype: the first 12 chromosomes. The genotype distances, their weights, the
// experiment's CSV and the genome JSON use these only.
inline constexpr std::size_t kPaperChromosomeCount = kKappaR;

struct Genome {
    std::array<double, kChromosomeCount> values{};

    double& operator[](std::size_t i) { return values[i]; }
    double operator[](std::size_t i) const { return values[i]; }

    double eta1() const { return values[kEta1]; }
    double eta2() const { return values[kEta2]; }
    double alpha1() const { return values[kAlpha1]; }
    double alpha2() const { return values[kAlpha2]; }
    double depth() const { return values[kDepth]; }
    std::array<double, 3> sigmaS() const {
        return {values[kSigmaSR], values[kSigmaSG], values[kSigmaSB]};
    }
    std::array<double, 3> sigmaA() const {
        return {values[kSigmaAR], values[kSigmaAG], values[kSigmaAB]};
    }
    double g() const { return values[kG]; }
    std::array<double, 3> kappa() const {
        return {values[kKappaR], values[kKappaG], values[kKappaB]};
    }
    // Whether the kappa genes are in use (hue variety); else they are 0 and the base's kappa
    // comes from the preset.
    bool carriesKappa() const {
        return values[kKappaR] > 0 || values[kKappaG] > 0 || values[kKappaB] > 0;
    }

    bool operator==(const Genome&) const = default;
};

// Stable names used in presets, CSV headers and the UI: "eta1", ..., "sigma_s_r", ..., "g",
// then "kappa_r", "kappa_g", "kappa_b".
std::string_view chromosomeName(std::size_t index);

}  // namespace matevo
