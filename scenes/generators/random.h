#pragma once
// A deterministic pseudo-random source for the scene generators. The standard distributions
// (std::uniform_real_distribution, ...) are implementation-defined, so the same seed could give
// different scenes with another standard library; everything here is fixed arithmetic.
#include <cstdint>

namespace shadowlab::scenegen {

// SplitMix64 (Steele, Lea, Flood 2014): expands one 64-bit seed into well-mixed state words.
inline std::uint64_t splitMix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// PCG32 (O'Neill 2014, XSH-RR output) seeded through SplitMix64; `stream` separates
// independent sequences from one seed (terrain, placement, colours), so changing how many
// numbers one part draws does not shift the others.
class Random {
public:
    explicit Random(std::uint64_t seed, std::uint64_t stream = 0) {
        std::uint64_t s = seed ^ (stream * 0xD1B54A32D192ED03ull);
        increment_ = (splitMix64(s) << 1u) | 1u;
        state_ = splitMix64(s);
        next();
    }

    std::uint32_t next() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + increment_;
        const auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
        const auto rot = std::uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    // Uniform in [0, 1): the top 24 bits, exactly representable as float and double.
    double unit() { return double(next() >> 8) * (1.0 / 16777216.0); }
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    // Uniform integer in [0, n) by multiply-shift (Lemire), n > 0; the tiny bias is irrelevant here.
    std::uint32_t below(std::uint32_t n) { return std::uint32_t((std::uint64_t(next()) * n) >> 32); }

private:
    std::uint64_t state_ = 0;
    std::uint64_t increment_ = 1;
};

}  // namespace shadowlab::scenegen
