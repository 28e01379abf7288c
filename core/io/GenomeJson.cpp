#include "io/GenomeJson.h"

#include <nlohmann/json.hpp>

#include "io/InputFile.h"
#include "io/JsonReader.h"
#include "io/TextFile.h"

namespace matevo {

namespace {

// Generous physical bounds; the family's Table 2 rules are checked separately.
constexpr double kMaxChromosomeValue = 1000.0;

}  // namespace

nlohmann::json genomeToJson(const Genome& genome) {
    return {{"eta1", genome.eta1()},       {"eta2", genome.eta2()},
            {"alpha1", genome.alpha1()},   {"alpha2", genome.alpha2()},
            {"depth", genome.depth()},     {"sigma_s", genome.sigmaS()},
            {"sigma_a", genome.sigmaA()},  {"g", genome.g()}};
}

nlohmann::json familyToJson(const MaterialFamily& family) {
    return {{"coat", toString(family.coat)},
            {"base", toString(family.base)},
            {"medium", family.hasMedium},
            {"textured_layer", toString(family.texturedLayer)}};
}

nlohmann::json materialToJson(const Genome& genome, const MaterialFamily& family,
                              const std::array<double, 3>& baseKappa) {
    nlohmann::json json = {{"family", familyToJson(family)}, {"genome", genomeToJson(genome)}};
    if (family.base == Base::Conductor) json["base_kappa"] = baseKappa;
    return json;
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

Result<Genome> parseGenome(std::string_view text, const std::string& sourceName) {
    std::vector<std::string> warnings;
    try {
        auto json = nlohmann::json::parse(text);
        // A result.json or a population entry holds the genome under "genome"; accept both.
        const auto& object = json.is_object() && json.contains("genome") ? json["genome"] : json;
        JsonReader reader(object, "", warnings);
        Genome genome = readGenome(reader);
        return genome;
    } catch (const nlohmann::json::exception& error) {
        return Error{sourceName + ": not valid JSON (" + error.what() + ")"};
    } catch (const JsonFieldError& error) {
        return Error{sourceName + ": " + error.what()};
    }
}

Result<Genome> loadGenome(const std::filesystem::path& file) {
    auto text = readTextFile(file);
    if (!text) return text.error();
    return parseGenome(*text, displayPath(file));
}

}  // namespace matevo
