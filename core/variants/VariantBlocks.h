#pragma once
// A large set cut into independent blocks, so that machines can share the work (docs/batch.md).
// A set of N variants in blocks of B is ⌈N / B⌉ blocks; block b holds the variants with indices
// b·B … b·B + B − 1 (the last block may be smaller) and is one variant search of its own, seeded
// from the run's seed and b alone (variantBlockSeed). So every variant depends only on the run's
// seed and its index, never on which process computed it or on any other block: K processes
// that each compute their share of the blocks write exactly the files of one process computing
// them all, and `matevo merge` joins them into those bytes.
//
// Distinctness: the search keeps the variants of one block at least `minApart` from each other
// (and checks it at the output size), as for any set. Across blocks nothing can be promised
// without making the blocks wait for each other; a whole set of thousands could not hold it
// anyway (a band around one target holds only so many variants `minApart` apart). Identical
// genomes in two blocks are found and reported (VariantBlockReport.h).
#include <cstdint>
#include <vector>

#include "variants/VariantSearch.h"

namespace matevo {

struct VariantBlocks {
    int count = 1;      // variants in the whole set
    int blockSize = 1;  // variants per block

    int blocks() const { return (count + blockSize - 1) / blockSize; }
    int firstIndex(int block) const { return block * blockSize; }
    int countIn(int block) const;
};

// Share `index` of `count` (0 ≤ index < count): blocks index, index + count, index + 2·count, …
// (round robin, so that shares differ by at most one block).
struct Shard {
    int index = 0;
    int count = 1;
};

// Block 0 keeps the run's seed, so a set of one block is the plain search for that seed; block
// b > 0 gets a SplitMix64 mix of the seed and b (an unrelated stream, not a neighbouring one).
std::uint64_t variantBlockSeed(std::uint64_t runSeed, int block);

// The request of one block: its count and seed; band and distance as the whole's.
VariantRequest blockRequest(const VariantRequest& whole, const VariantBlocks& plan, int block);

// The blocks a share computes, in increasing order.
std::vector<int> blocksOfShard(const VariantBlocks& plan, const Shard& shard);

}  // namespace matevo
