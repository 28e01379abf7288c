#pragma once
// A checkpoint of an evolve run, written after every generation so that a long run can stop and
// resume to the same end, bit for bit: the run's identity (family, target, kappa, GA settings)
// and its state (population with fitness, history, the random generator). Doubles are written
// with enough digits to read back exactly. Saving is atomic (files/AtomicFile.h).
//   {"format": "matevo-ga-checkpoint", "format_version": 1, "family": {…}, "base_kappa": […],
//    "target": {…}, "ga": {…}, "generation": G, "random_state": [4 integers],
//    "population": [{"genome": {…}, "fitness": f}, …], "history": [{…}, …]}
#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "common/Result.h"
#include "evolve/GaSettings.h"
#include "evolve/GeneticAlgorithm.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"

namespace matevo {

struct GaCheckpoint {
    MaterialFamily family;
    Genome target;
    std::array<double, 3> baseKappa = {0.0, 0.0, 0.0};
    GaSettings settings;
    GaState state;

    bool operator==(const GaCheckpoint&) const = default;
};

std::string serializeCheckpoint(const GaCheckpoint& checkpoint);
Status saveCheckpoint(const GaCheckpoint& checkpoint, const std::filesystem::path& file);
// Errors name the file and the field.
Result<GaCheckpoint> loadCheckpoint(const std::filesystem::path& file);
// The same for a checkpoint's text; `sourceName` names it in errors.
Result<GaCheckpoint> parseCheckpoint(const std::string& text, const std::string& sourceName);

// Why `checkpoint` cannot continue a run of (family, target, kappa, settings), or nothing when it
// can; the number of generations may differ (a run can be extended).
std::optional<std::string> checkpointMismatch(const GaCheckpoint& checkpoint,
                                              const MaterialFamily& family, const Genome& target,
                                              const std::array<double, 3>& baseKappa,
                                              const GaSettings& settings);

}  // namespace matevo
