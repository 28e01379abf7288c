#pragma once
// Seeds of the runs of one experiment. The paper (§5) changed the seed every 9 runs and let the
// generator run on in between, so the 9 runs of a block drew successive numbers from one
// stream. We keep that structure while making every run reproducible on its own:
//   block b = run / runsPerSeed has the seed  baseSeed + b;
//   run k of the block (k = run % runsPerSeed) gets as its GA seed the (k+1)-th output of a
//   SplitMix64 generator started from the block seed.
// So the runs of a block are successive draws from one generator, a new block restarts it from
// a new seed, and any run is replayed alone by `matevo evolve --seed <its seed>`. Every metric
// uses the same seeds, so the metrics are compared on paired runs.
#include <cstdint>

namespace matevo {

std::uint64_t blockSeed(std::uint64_t baseSeed, int run, int runsPerSeed);
std::uint64_t runSeed(std::uint64_t baseSeed, int run, int runsPerSeed);

}  // namespace matevo
