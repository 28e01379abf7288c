#include "genome/Genome.h"

namespace matevo {

std::string_view chromosomeName(std::size_t index) {
    static constexpr std::array<std::string_view, kChromosomeCount> kNames = {
        "eta1",      "eta2",      "alpha1",    "alpha2",    "depth",
        "sigma_s_r", "sigma_s_g", "sigma_s_b", "sigma_a_r", "sigma_a_g",
        "sigma_a_b", "g",         "kappa_r",   "kappa_g",   "kappa_b"};
    return index < kNames.size() ? kNames[index] : std::string_view("?");
}

}  // namespace matevo
