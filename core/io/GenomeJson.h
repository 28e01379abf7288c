#pragma once
// The genome's JSON form, shared by presets, `evolve --json` and `render --genome`:
// {"eta1":…, "eta2":…, "alpha1":…, "alpha2":…, "depth":…, "sigma_s":[r,g,b],
//  "sigma_a":[r,g,b], "g":…}. The medium fields may be left out (they default to 0).
#include <array>
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "common/Result.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"

namespace matevo {

class JsonReader;

nlohmann::json genomeToJson(const Genome& genome);
// {"coat":…, "base":…, "medium":…, "textured_layer":…}, as presets store it.
nlohmann::json familyToJson(const MaterialFamily& family);
// A genome with what it is rendered with, as a variant file stores it: {"family": {…},
// "base_kappa": [r,g,b] (conductor base only), "genome": {…}}. loadGenome reads its genome.
nlohmann::json materialToJson(const Genome& genome, const MaterialFamily& family,
                              const std::array<double, 3>& baseKappa);
Genome readGenome(JsonReader& reader);  // throws JsonFieldError naming the field
// The genome JSON in `text`; errors name `sourceName` and the field.
Result<Genome> parseGenome(std::string_view text, const std::string& sourceName);
Result<Genome> loadGenome(const std::filesystem::path& file);

}  // namespace matevo
