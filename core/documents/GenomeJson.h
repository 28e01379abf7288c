#pragma once
// The genome's JSON form, shared by presets, `evolve --json` and `render --genome`:
// {"eta1":…, "eta2":…, "alpha1":…, "alpha2":…, "depth":…, "sigma_s":[r,g,b],
//  "sigma_a":[r,g,b], "g":…}. The medium fields may be left out (they default to 0). A genome
// alone does not say how to render it: files carry it inside a material file (MaterialFile.h).
#include <nlohmann/json_fwd.hpp>

#include "genome/Genome.h"

namespace matevo {

class JsonReader;

nlohmann::ordered_json genomeToJson(const Genome& genome);
Genome readGenome(JsonReader& reader);  // throws JsonFieldError naming the field

}  // namespace matevo
