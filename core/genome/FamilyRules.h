#pragma once
// Table 2 of Bernardi et al. (2020) as data: for each material family, the range of every
// chromosome and the relation between the two refractive indices. Where the paper leaves a range
// open we close it; docs/genome-ranges.md gives every bound and the reason for it.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "genome/Genome.h"
#include "genome/MaterialFamily.h"

namespace matevo {

// An interval of allowed values with inclusive or exclusive ends. An inactive chromosome (the
// medium of a family without one) is pinned to a single value and never varied.
struct ChromosomeRange {
    double min = 0;
    double max = 0;
    bool minInclusive = true;
    bool maxInclusive = true;
    bool active = true;

    bool contains(double value) const {
        return (minInclusive ? value >= min : value > min) &&
               (maxInclusive ? value <= max : value < max);
    }
    double width() const { return max - min; }
    bool empty() const { return !(min < max || (min == max && minInclusive && maxInclusive)); }
};

// The part of two ranges allowed by both, with the stricter end at each side.
ChromosomeRange intersect(const ChromosomeRange& a, const ChromosomeRange& b);

// Which side of eta1 eta2 lies on. Footnote a (conductor base): eta2 slightly below eta1, to
// favour internal reflection. Footnote b (dielectric base): eta2 above eta1, for transmission.
enum class EtaDirection { Eta2Below, Eta2Above };

// |eta1 - eta2| in (0, maxDifference], with eta2 on the given side of eta1.
struct EtaRelation {
    EtaDirection direction = EtaDirection::Eta2Below;
    double maxDifference = 0;

    bool holds(double eta1, double eta2) const {
        const double difference = direction == EtaDirection::Eta2Below ? eta1 - eta2 : eta2 - eta1;
        return difference > 0 && difference <= maxDifference;
    }
};

// The value every inactive chromosome is pinned to (no medium: depth 0 drops the medium slot).
inline constexpr double kInactiveChromosomeValue = 0.0;

struct FamilyRules {
    // eta2's entry is its absolute range over every allowed eta1; the relation narrows it.
    std::array<ChromosomeRange, kChromosomeCount> ranges{};
    EtaRelation etaRelation;

    // The eta2 values allowed beside this eta1 (absolute range and relation); never empty for
    // an eta1 inside its range.
    ChromosomeRange eta2Given(double eta1) const;
    // The eta1 values allowed beside this eta2; never empty for an eta2 of a valid genome.
    ChromosomeRange eta1Given(double eta2) const;
    // Whether this (eta1, eta2) pair is allowed: both in range and the relation holds.
    bool etasCompatible(double eta1, double eta2) const {
        return ranges[kEta1].contains(eta1) && ranges[kEta2].contains(eta2) &&
               etaRelation.holds(eta1, eta2);
    }
};

// Hue variety, beyond the paper: whether the conductor base's kappa genes are evolved.
enum class KappaGenes { Off, On };

// The bounds of each kappa gene when they are on: every channel stays a conductor (kappa_rel =
// kappa / eta1 >= 0.5 for eta1 <= 2) and inside the FGD table (kappa_rel <= 4 since eta1 > 1).
// At the validation presets' eta2 / eta1 = 2/3 that spans a normal-incidence reflectance of
// 0.29 (kappa 1) to 0.86 (kappa 4) per channel.
inline constexpr double kKappaGeneMin = 1.0;
inline constexpr double kKappaGeneMax = 4.0;

// Table 2 pairs texturing with the coat: a roughcoat textures its rough top layer, a clearcoat
// its rough bottom layer. nullopt for a supported family, else why it is not.
std::optional<std::string> validateFamily(const MaterialFamily& family);
// Every family validateFamily accepts (16: coat x base x medium x {none, the rough layer}).
std::vector<MaterialFamily> supportedFamilies();

// With KappaGenes::On and a conductor base, the kappa genes are active in [kKappaGeneMin,
// kKappaGeneMax]; otherwise they are inactive (pinned to 0) like an absent medium.
FamilyRules familyRules(const MaterialFamily& family, KappaGenes kappaGenes = KappaGenes::Off);
ChromosomeRange chromosomeRange(const MaterialFamily& family, std::size_t index);

// nullopt when the genome satisfies Table 2 for the family, else a message naming the
// chromosome and the violated rule.
std::optional<std::string> validateGenome(const Genome& genome, const FamilyRules& rules);
std::optional<std::string> validateGenome(const Genome& genome, const MaterialFamily& family);

// "[0.1, 4]", "(1, 2]" — for messages and documentation.
std::string describe(const ChromosomeRange& range);

}  // namespace matevo
