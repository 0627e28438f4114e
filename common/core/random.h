#pragma once
// A small seeded generator (PCG32) whose sequence is the same on every platform and standard library, so
// headless games, tests and benchmarks are reproducible. (std::uniform_*_distribution is not portable.)
#include <cstdint>

namespace ks {

class Rng {
public:
    explicit Rng(std::uint64_t seed = 0x853c49e6748fea9bULL, std::uint64_t stream = 0xda3e39cb94b95bdbULL) {
        inc_ = (stream << 1u) | 1u;
        next_u32();
        state_ += seed;
        next_u32();
    }

    std::uint32_t next_u32() {
        std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
    }

    // Uniform in [0, 1) with 24 bits, exactly representable as float.
    float uniform() { return static_cast<float>(next_u32() >> 8) * (1.0f / 16777216.0f); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    // Uniform in [0, 1) with 53 bits.
    double uniform_double() {
        std::uint64_t hi = next_u32() >> 5, lo = next_u32() >> 6;
        return static_cast<double>(hi * 67108864ULL + lo) * (1.0 / 9007199254740992.0);
    }
    // Uniform integer in [0, bound) without modulo bias.
    std::uint32_t below(std::uint32_t bound) {
        if (bound == 0) return 0;
        std::uint32_t threshold = (-bound) % bound;
        for (;;) {
            std::uint32_t r = next_u32();
            if (r >= threshold) return r % bound;
        }
    }
    bool chance(float probability) { return uniform() < probability; }

    std::uint64_t state() const { return state_; }

private:
    std::uint64_t state_ = 0;
    std::uint64_t inc_ = 0;
};

} // namespace ks
