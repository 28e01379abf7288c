#include "variants/VariantBlocks.h"

#include <algorithm>

#include "evolve/Random.h"

namespace matevo {

int VariantBlocks::countIn(int block) const {
    return std::clamp(count - firstIndex(block), 0, blockSize);
}

std::uint64_t variantBlockSeed(std::uint64_t runSeed, int block) {
    if (block == 0) return runSeed;
    return SplitMix64(runSeed ^ SplitMix64(std::uint64_t(block)).next()).next();
}

VariantRequest blockRequest(const VariantRequest& whole, const VariantBlocks& plan, int block) {
    VariantRequest request = whole;
    request.count = plan.countIn(block);
    request.seed = variantBlockSeed(whole.seed, block);
    return request;
}

std::vector<int> blocksOfShard(const VariantBlocks& plan, const Shard& shard) {
    std::vector<int> blocks;
    for (int block = shard.index; block < plan.blocks(); block += shard.count)
        blocks.push_back(block);
    return blocks;
}

}  // namespace matevo
