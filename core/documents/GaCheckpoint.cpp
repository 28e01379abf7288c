#include "documents/GaCheckpoint.h"

#include <nlohmann/json.hpp>

#include "documents/GenomeJson.h"
#include "documents/PresetFieldsJson.h"
#include "files/AtomicFile.h"
#include "files/JsonReader.h"
#include "files/TextFile.h"

namespace matevo {

namespace {

constexpr const char* kCheckpointFormat = "matevo-ga-checkpoint";
constexpr int kCheckpointVersion = 1;
constexpr double kLargest = 1e300;  // fitness and statistics: any finite value

GenerationStats readStats(JsonReader reader) {
    GenerationStats stats;
    stats.generation = int(reader.integer("generation", 0, kMaxGenerations));
    stats.best = reader.number("best", -kLargest, kLargest);
    stats.mean = reader.number("mean", -kLargest, kLargest);
    stats.worst = reader.number("worst", -kLargest, kLargest);
    stats.diversity = reader.number("diversity", 0.0, kLargest);
    return stats;
}

GaCheckpoint readCheckpoint(JsonReader& root, const nlohmann::json& json) {
    if (root.string("format") != kCheckpointFormat)
        root.fail("format", std::string("must be \"") + kCheckpointFormat + "\"");
    if (root.integer("format_version", 1, kCheckpointVersion) != kCheckpointVersion)
        root.fail("format_version", "unsupported");
    GaCheckpoint checkpoint;
    checkpoint.family = readFamily(root, "family");
    checkpoint.baseKappa = readBaseKappa(root, checkpoint.family);
    // Genomes are checked against the family's Table 2 rules, as a preset's are: a tampered
    // checkpoint must not carry a material outside them into a result.
    checkpoint.target = readFamilyGenome(root, "target", checkpoint.family);
    checkpoint.settings = readGaSettings(root.object("ga"));
    GaState& state = checkpoint.state;
    state.generation = int(root.integer("generation", 0, kMaxGenerations));
    if (!root.has("random_state")) root.fail("random_state", "missing");
    const auto& random = json["random_state"];
    if (!random.is_array() || random.size() != 4) root.fail("random_state", "must be 4 integers");
    for (std::size_t i = 0; i < 4; ++i) {
        if (!random[i].is_number_unsigned()) root.fail("random_state", "must be 4 integers");
        state.random[i] = random[i].get<std::uint64_t>();
    }
    for (const char* key : {"population", "history"})
        if (!json.contains(key) || !json[key].is_array()) root.fail(key, "must be an array");
    const auto& population = json["population"];
    for (std::size_t i = 0; i < population.size(); ++i) {
        std::vector<std::string> ignored;
        JsonReader entry(population[i], "population[" + std::to_string(i) + "]", ignored);
        state.population.push_back({readFamilyGenome(entry, "genome", checkpoint.family),
                                    entry.number("fitness", -kLargest, kLargest)});
    }
    const auto& history = json["history"];
    for (std::size_t i = 0; i < history.size(); ++i) {
        std::vector<std::string> ignored;
        state.history.push_back(
            readStats(JsonReader(history[i], "history[" + std::to_string(i) + "]", ignored)));
    }
    return checkpoint;
}

nlohmann::ordered_json statsToJson(const GenerationStats& stats) {
    return {{"generation", stats.generation},
            {"best", stats.best},
            {"mean", stats.mean},
            {"worst", stats.worst},
            {"diversity", stats.diversity}};
}

}  // namespace

std::string serializeCheckpoint(const GaCheckpoint& checkpoint) {
    nlohmann::ordered_json json = {{"format", kCheckpointFormat},
                                   {"format_version", kCheckpointVersion},
                                   {"family", familyToJson(checkpoint.family)},
                                   {"base_kappa", checkpoint.baseKappa},
                                   {"target", genomeToJson(checkpoint.target)},
                                   {"ga", gaSettingsToJson(checkpoint.settings)},
                                   {"generation", checkpoint.state.generation},
                                   {"random_state", checkpoint.state.random}};
    nlohmann::ordered_json population = nlohmann::ordered_json::array();
    for (const auto& individual : checkpoint.state.population)
        population.push_back(
            {{"genome", genomeToJson(individual.genome)}, {"fitness", individual.fitness}});
    json["population"] = std::move(population);
    nlohmann::ordered_json history = nlohmann::ordered_json::array();
    for (const auto& stats : checkpoint.state.history) history.push_back(statsToJson(stats));
    json["history"] = std::move(history);
    return json.dump(1) + "\n";
}

Status saveCheckpoint(const GaCheckpoint& checkpoint, const std::filesystem::path& file) {
    return writeFileAtomically(file, serializeCheckpoint(checkpoint));
}

Result<GaCheckpoint> loadCheckpoint(const std::filesystem::path& file) {
    auto text = readTextFile(file);
    if (!text) return text.error();
    return parseCheckpoint(*text, file.string());
}

Result<GaCheckpoint> parseCheckpoint(const std::string& text, const std::string& sourceName) {
    std::vector<std::string> ignored;  // a checkpoint is machine-written: no warnings to give
    return readJsonDocument<GaCheckpoint>(text, sourceName, ignored,
                                          [&](const nlohmann::json& json) {
                                              JsonReader root(json, "", ignored);
                                              return readCheckpoint(root, json);
                                          });
}

std::optional<std::string> checkpointMismatch(const GaCheckpoint& checkpoint,
                                              const MaterialFamily& family, const Genome& target,
                                              const std::array<double, 3>& baseKappa,
                                              const GaSettings& settings) {
    GaSettings sameLength = checkpoint.settings;
    sameLength.generations = settings.generations;
    if (checkpoint.family != family) return "family: the checkpoint is of another family";
    if (checkpoint.target != target) return "target: the checkpoint has another target";
    if (checkpoint.baseKappa != baseKappa) return "base_kappa: the checkpoint has another kappa";
    if (sameLength != settings)
        return "ga: the checkpoint was made with other GA settings (population, metric, weights, "
               "normalisation, elitism or seed)";
    if (checkpoint.state.generation > settings.generations)
        return "generation: the checkpoint is at generation " +
               std::to_string(checkpoint.state.generation) + ", past the " +
               std::to_string(settings.generations) + " asked for";
    return std::nullopt;
}

}  // namespace matevo
