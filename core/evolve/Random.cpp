#include "evolve/Random.h"

namespace matevo {

Random::Random(std::uint64_t seed) {
    SplitMix64 seeder(seed);
    for (auto& word : state_) word = seeder.next();
}

Random Random::fromState(const State& state) {
    Random random;
    random.state_ = state;
    return random;
}

}  // namespace matevo
