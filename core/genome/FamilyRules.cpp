#include "genome/FamilyRules.h"

#include <algorithm>
#include <cstdio>

namespace matevo {
namespace {

constexpr ChromosomeRange closed(double min, double max) { return {min, max, true, true, true}; }
constexpr ChromosomeRange closedOpen(double min, double max) {
    return {min, max, true, false, true};
}
constexpr ChromosomeRange openClosed(double min, double max) {
    return {min, max, false, true, true};
}
constexpr ChromosomeRange inactive() {
    return {kInactiveChromosomeValue, kInactiveChromosomeValue, true, true, false};
}

// Bounds Table 2 leaves open, closed by us (docs/genome-ranges.md explains each).
// GGX roughness beyond 1 leaves the range Belcour's tables cover (the model clamps at 0.9999).
constexpr double kRoughAlphaMax = 1.0;
// A textured layer's alpha multiplies a texel in [0, 1]; painted metal uses 2.5, so a weight
// of up to 4 lets the texture's bright texels reach fully rough.
constexpr double kTexturedAlphaWeightMax = 4.0;
// Footnote a only bounds eta2 by eta1 - 1.5, which can be negative; an IOR must stay positive
// and 0.1 sits below the real part of silver and gold in the visible range.
constexpr double kConductorEta2Min = 0.1;

// One cell of Table 2: a coat over a base, without a medium.
struct CoatBaseRules {
    Coat coat;
    Base base;
    ChromosomeRange alpha1;
    ChromosomeRange alpha2;
    ChromosomeRange eta1;
    // Absolute eta2 range: conductors stay below eta1 (<= 2); dielectrics need eta2 >= 1
    // (footnote b) and reach at most max eta1 + the largest difference.
    ChromosomeRange eta2;
    EtaRelation etaRelation;
};

constexpr std::array<CoatBaseRules, 4> kTable2 = {{
    {Coat::Roughcoat,
     Base::Conductor,
     closed(0.1, kRoughAlphaMax),
     closedOpen(0.0, 0.1),
     openClosed(1.0, 2.0),
     closedOpen(kConductorEta2Min, 2.0),
     {EtaDirection::Eta2Below, 1.5}},
    {Coat::Roughcoat,
     Base::Dielectric,
     closed(0.1, kRoughAlphaMax),
     closedOpen(0.0, 0.01),
     openClosed(1.0, 2.0),
     closed(1.0, 2.5),
     {EtaDirection::Eta2Above, 0.5}},
    {Coat::Clearcoat,
     Base::Conductor,
     closedOpen(0.0, 0.1),
     closed(0.1, kRoughAlphaMax),
     openClosed(1.0, 2.0),
     closedOpen(kConductorEta2Min, 2.0),
     {EtaDirection::Eta2Below, 1.5}},
    {Coat::Clearcoat,
     Base::Dielectric,
     closedOpen(0.0, 0.01),
     closed(0.01, kRoughAlphaMax),
     openClosed(1.0, 3.0),
     closed(1.0, 6.0),
     {EtaDirection::Eta2Above, 3.0}},
}};

// The participating-medium row of Table 2 (the second sigma_s line there is sigma_a).
constexpr ChromosomeRange kDepthRange = closed(0.05, 40.0);
constexpr ChromosomeRange kCrossSectionRange = closed(0.0, 1.0);
// Henyey-Greenstein g: the model's variance term is valid only for strongly forward scattering
// (g >~ 0.7, docs/bsdf.md 2.6); g = 1 is a delta phase function, so stop at 0.99.
constexpr ChromosomeRange kAnisotropyRange = closed(0.7, 0.99);
// Footnote d: with a medium over a conductor, eta2 < 1.
constexpr ChromosomeRange kConductorEta2WithMedium = closedOpen(kConductorEta2Min, 1.0);

const CoatBaseRules& coatBaseRules(Coat coat, Base base) {
    const auto* rules = std::find_if(kTable2.begin(), kTable2.end(), [&](const auto& row) {
        return row.coat == coat && row.base == base;
    });
    return *rules;  // the table covers every coat x base
}

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

std::string outOfRangeMessage(std::size_t index, double value, const ChromosomeRange& range) {
    return std::string(chromosomeName(index)) + " = " + formatNumber(value) + " is outside " +
           describe(range) + " (Table 2)";
}

}  // namespace

ChromosomeRange intersect(const ChromosomeRange& a, const ChromosomeRange& b) {
    ChromosomeRange result = a;
    if (b.min > a.min || (b.min == a.min && !b.minInclusive)) {
        result.min = b.min;
        result.minInclusive = b.minInclusive;
    }
    if (b.max < a.max || (b.max == a.max && !b.maxInclusive)) {
        result.max = b.max;
        result.maxInclusive = b.maxInclusive;
    }
    result.active = a.active && b.active;
    return result;
}

ChromosomeRange FamilyRules::eta2Given(double eta1) const {
    const double reach = etaRelation.maxDifference;
    const ChromosomeRange byRelation = etaRelation.direction == EtaDirection::Eta2Below
                                           ? closedOpen(eta1 - reach, eta1)
                                           : openClosed(eta1, eta1 + reach);
    return intersect(ranges[kEta2], byRelation);
}

ChromosomeRange FamilyRules::eta1Given(double eta2) const {
    const double reach = etaRelation.maxDifference;
    const ChromosomeRange byRelation = etaRelation.direction == EtaDirection::Eta2Below
                                           ? openClosed(eta2, eta2 + reach)
                                           : closedOpen(eta2 - reach, eta2);
    return intersect(ranges[kEta1], byRelation);
}

std::optional<std::string> validateFamily(const MaterialFamily& family) {
    if (family.texturedLayer == TexturedLayer::Top && family.coat != Coat::Roughcoat)
        return "textured layer 'top' needs a roughcoat: Table 2 textures the rough layer, which "
               "for a clearcoat is the bottom one";
    if (family.texturedLayer == TexturedLayer::Bottom && family.coat != Coat::Clearcoat)
        return "textured layer 'bottom' needs a clearcoat: Table 2 textures the rough layer, "
               "which for a roughcoat is the top one";
    return std::nullopt;
}

std::vector<MaterialFamily> supportedFamilies() {
    std::vector<MaterialFamily> families;
    for (Coat coat : {Coat::Roughcoat, Coat::Clearcoat})
        for (Base base : {Base::Conductor, Base::Dielectric})
            for (bool hasMedium : {false, true})
                for (TexturedLayer layer :
                     {TexturedLayer::None, TexturedLayer::Top, TexturedLayer::Bottom}) {
                    const MaterialFamily family{coat, base, hasMedium, layer};
                    if (!validateFamily(family)) families.push_back(family);
                }
    return families;
}

FamilyRules familyRules(const MaterialFamily& family, KappaGenes kappaGenes) {
    const CoatBaseRules& cell = coatBaseRules(family.coat, family.base);
    FamilyRules rules;
    rules.etaRelation = cell.etaRelation;
    rules.ranges[kEta1] = cell.eta1;
    rules.ranges[kEta2] = cell.eta2;
    rules.ranges[kAlpha1] = cell.alpha1;
    rules.ranges[kAlpha2] = cell.alpha2;
    // A textured layer's alpha is a weight on the texel; it keeps Table 2's lower bound.
    if (family.texturedLayer == TexturedLayer::Top)
        rules.ranges[kAlpha1] = closed(cell.alpha1.min, kTexturedAlphaWeightMax);
    if (family.texturedLayer == TexturedLayer::Bottom)
        rules.ranges[kAlpha2] = closed(cell.alpha2.min, kTexturedAlphaWeightMax);

    for (std::size_t i = kDepth; i < kChromosomeCount; ++i) rules.ranges[i] = inactive();
    if (family.hasMedium) {
        rules.ranges[kDepth] = kDepthRange;
        for (std::size_t i = kSigmaSR; i <= kSigmaAB; ++i) rules.ranges[i] = kCrossSectionRange;
        rules.ranges[kG] = kAnisotropyRange;
        if (family.base == Base::Conductor)
            rules.ranges[kEta2] = intersect(cell.eta2, kConductorEta2WithMedium);
    }
    if (kappaGenes == KappaGenes::On && family.base == Base::Conductor)
        for (std::size_t i = kKappaR; i <= kKappaB; ++i)
            rules.ranges[i] = closed(kKappaGeneMin, kKappaGeneMax);
    return rules;
}

ChromosomeRange chromosomeRange(const MaterialFamily& family, std::size_t index) {
    return familyRules(family).ranges.at(index);
}

std::optional<std::string> validateGenome(const Genome& genome, const FamilyRules& rules) {
    for (std::size_t i = 0; i < kChromosomeCount; ++i) {
        const ChromosomeRange& range = rules.ranges[i];
        if (!range.active && genome[i] != range.min)
            return std::string(chromosomeName(i)) + " = " + formatNumber(genome[i]) + " but " +
                   (i >= kPaperChromosomeCount ? "the kappa genes are off"
                                               : "the family has no medium") +
                   ": it must be " + formatNumber(range.min);
        if (!range.contains(genome[i])) return outOfRangeMessage(i, genome[i], range);
    }
    const EtaRelation& relation = rules.etaRelation;
    if (!relation.holds(genome.eta1(), genome.eta2())) {
        const bool below = relation.direction == EtaDirection::Eta2Below;
        return "eta2 = " + formatNumber(genome.eta2()) +
               " with eta1 = " + formatNumber(genome.eta1()) + ": eta2 must lie " +
               (below ? "below" : "above") + " eta1 with |eta1 - eta2| in (0, " +
               formatNumber(relation.maxDifference) + "] (Table 2, footnote " +
               (below ? "a" : "b") + ")";
    }
    return std::nullopt;
}

std::optional<std::string> validateGenome(const Genome& genome, const MaterialFamily& family) {
    if (auto problem = validateFamily(family)) return problem;
    return validateGenome(genome, familyRules(family));
}

std::string describe(const ChromosomeRange& range) {
    if (!range.active) return "fixed at " + formatNumber(range.min);
    std::string text(range.minInclusive ? "[" : "(");
    text += formatNumber(range.min) + ", " + formatNumber(range.max);
    text += range.maxInclusive ? "]" : ")";
    return text;
}

}  // namespace matevo
