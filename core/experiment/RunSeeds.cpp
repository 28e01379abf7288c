#include "experiment/RunSeeds.h"

#include "evolve/Random.h"

namespace matevo {

std::uint64_t blockSeed(std::uint64_t baseSeed, int run, int runsPerSeed) {
    return baseSeed + std::uint64_t(run / runsPerSeed);
}

std::uint64_t runSeed(std::uint64_t baseSeed, int run, int runsPerSeed) {
    SplitMix64 blockStream(blockSeed(baseSeed, run, runsPerSeed));
    std::uint64_t seed = blockStream.next();
    for (int draw = 0; draw < run % runsPerSeed; ++draw) seed = blockStream.next();
    return seed;
}

}  // namespace matevo
