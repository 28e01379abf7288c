#pragma once
// Our own pseudo-random numbers: xoshiro256** (Blackman & Vigna) seeded through SplitMix64, with
// our own distributions. std::uniform_*_distribution differ between standard libraries; these do
// not, so one seed gives bit-identical results on every machine.
#include <array>
#include <cstdint>

namespace matevo {

// SplitMix64 (Steele, Lea & Flood): spreads one 64-bit seed over xoshiro's 256-bit state, so
// that nearby seeds give unrelated streams and the state is never all zero.
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }

private:
    std::uint64_t state_;
};

class Random {
public:
    using State = std::array<std::uint64_t, 4>;

    explicit Random(std::uint64_t seed);
    // For known-answer tests against the published xoshiro256** outputs. Must not be all zero.
    static Random fromState(const State& state);

    // xoshiro256**: 64 uniformly distributed bits.
    std::uint64_t next() {
        const std::uint64_t result = rotateLeft(state_[1] * 5, 7) * 9;
        const std::uint64_t t = state_[1] << 17;
        state_[2] ^= state_[0];
        state_[3] ^= state_[1];
        state_[1] ^= state_[2];
        state_[0] ^= state_[3];
        state_[2] ^= t;
        state_[3] = rotateLeft(state_[3], 45);
        return result;
    }

    // Uniform in [0, 1) on the grid of multiples of 2^-53: the top 53 bits, exactly representable.
    // (Converting through int64 is exact here and compiles to one instruction.)
    double uniform() {
        return static_cast<double>(static_cast<std::int64_t>(next() >> 11)) * 0x1.0p-53;
    }

    // Uniform integer in [0, bound) without modulo bias (Lemire 2019, multiply and reject the
    // few low products that would over-represent some values). bound must be > 0.
    std::uint64_t below(std::uint64_t bound) {
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

    // True with probability p (p <= 0 never, p >= 1 always).
    bool bernoulli(double p) { return uniform() < p; }

    const State& state() const { return state_; }

private:
    Random() = default;

    static std::uint64_t rotateLeft(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

    State state_{};
};

}  // namespace matevo
