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

std::uint64_t Random::below(std::uint64_t bound) {
    __extension__ using Uint128 = unsigned __int128;
    Uint128 product = static_cast<Uint128>(next()) * bound;
    auto low = static_cast<std::uint64_t>(product);
    if (low < bound) {
        // 2^64 mod bound: products whose low word falls below it are the surplus ones.
        const std::uint64_t threshold = (0 - bound) % bound;
        while (low < threshold) {
            product = static_cast<Uint128>(next()) * bound;
            low = static_cast<std::uint64_t>(product);
        }
    }
    return static_cast<std::uint64_t>(product >> 64);
}

}  // namespace matevo
