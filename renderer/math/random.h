#pragma once
// A reproducible random source for the stress suite and the method sweep: std::mt19937_64 is
// fully specified by the standard, so cases reproduce across platforms; the distributions are
// written by hand because std:: distributions are not.
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <random>

namespace shadowlab {

struct Rng {
    std::mt19937_64 g;
    explicit Rng(std::uint64_t seed) : g(seed) {}
    double uniform() { return double(g() >> 11) * (1.0 / 9007199254740992.0); }
    double uniform(double a, double b) { return a + (b - a) * uniform(); }
    double logUniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
    int pick(int n) { return int(uniform() * n) % n; }
    bool chance(double p) { return uniform() < p; }
    glm::dvec3 unit() {
        for (;;) {
            const glm::dvec3 v{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
            const double l = glm::length(v);
            if (l > 1e-3 && l <= 1.0) return v / l;
        }
    }
};

}  // namespace shadowlab
