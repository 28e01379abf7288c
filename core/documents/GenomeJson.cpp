#include "documents/GenomeJson.h"

#include <nlohmann/json.hpp>

#include "files/JsonReader.h"

namespace matevo {

namespace {

// Generous physical bounds; the family's Table 2 rules are checked separately.
constexpr double kMaxChromosomeValue = 1000.0;

}  // namespace

nlohmann::ordered_json genomeToJson(const Genome& genome) {
    return {{"eta1", genome.eta1()},      {"eta2", genome.eta2()},   {"alpha1", genome.alpha1()},
            {"alpha2", genome.alpha2()},  {"depth", genome.depth()}, {"sigma_s", genome.sigmaS()},
            {"sigma_a", genome.sigmaA()}, {"g", genome.g()}};
}

Genome readGenome(JsonReader& reader) {
    Genome genome;
    genome[kEta1] = reader.number("eta1", 0.0, kMaxChromosomeValue);
    genome[kEta2] = reader.number("eta2", 0.0, kMaxChromosomeValue);
    genome[kAlpha1] = reader.number("alpha1", 0.0, kMaxChromosomeValue);
    genome[kAlpha2] = reader.number("alpha2", 0.0, kMaxChromosomeValue);
    if (reader.has("depth")) genome[kDepth] = reader.number("depth", 0.0, kMaxChromosomeValue);
    if (reader.has("sigma_s")) {
        auto sigmaS = reader.numbers<3>("sigma_s", 0.0, kMaxChromosomeValue);
        for (std::size_t c = 0; c < 3; ++c) genome[kSigmaSR + c] = sigmaS[c];
    }
    if (reader.has("sigma_a")) {
        auto sigmaA = reader.numbers<3>("sigma_a", 0.0, kMaxChromosomeValue);
        for (std::size_t c = 0; c < 3; ++c) genome[kSigmaAR + c] = sigmaA[c];
    }
    if (reader.has("g")) genome[kG] = reader.number("g", -1.0, 1.0);
    return genome;
}

}  // namespace matevo
