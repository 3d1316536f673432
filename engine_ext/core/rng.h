// The project's seeded random number generator: PCG32 (O'Neill 2014, "PCG: A Family of
// Simple Fast Space-Efficient Statistically Good Algorithms"). Used instead of std::rand
// and std::*_distribution, whose output differs between standard libraries; every
// conversion to floating point below is spelled out so results are bit-identical everywhere.
#pragma once

#include <cstdint>

namespace obscura {

class Rng {
public:
    explicit Rng(std::uint64_t seed = 0x853c49e6748fea9bULL, std::uint64_t stream = 0xda3e39cb94b95bdbULL) {
        reseed(seed, stream);
    }

    void reseed(std::uint64_t seed, std::uint64_t stream = 0xda3e39cb94b95bdbULL) {
        state_ = 0;
        inc_ = (stream << 1u) | 1u;
        nextU32();
        state_ += seed;
        nextU32();
    }

    std::uint32_t nextU32() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
    }

    // Uniform in [0, bound) without modulo bias (Lemire's rejection on the low bits).
    std::uint32_t below(std::uint32_t bound) {
        if (bound == 0) return 0;
        const std::uint32_t threshold = (0u - bound) % bound;
        for (;;) {
            const std::uint32_t r = nextU32();
            if (r >= threshold) return r % bound;
        }
    }

    // Uniform float in [0, 1): the top 24 bits scaled exactly by 2^-24.
    float uniform01() { return static_cast<float>(nextU32() >> 8) * (1.0f / 16777216.0f); }
    // Uniform float in [lo, hi).
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform01(); }
    // Uniform double in [0, 1) from 53 random bits.
    double uniform01d() {
        const std::uint64_t hi = nextU32() >> 5, lo = nextU32() >> 6;  // 27 + 26 bits
        return static_cast<double>((hi << 26) | lo) * (1.0 / 9007199254740992.0);
    }

    std::uint64_t state() const { return state_; }
    std::uint64_t increment() const { return inc_; }

private:
    std::uint64_t state_ = 0;
    std::uint64_t inc_ = 1;
};

}  // namespace obscura
