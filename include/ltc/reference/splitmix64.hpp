// ltc/reference/splitmix64.hpp -- the random numbers of the Monte Carlo ground truth
// (ltc/reference/ground_truth.hpp), also drawn by the tests and the benchmarks' configurations.
//
//   ltc::ground_truth::splitmix64 rng(seed);
//   glm::dvec2 u = rng.uniform2();   // uniform in [0, 1)^2
//
// A fixed seed gives the same numbers on every platform: SplitMix64, doubles from the top 53
// bits, no <random> distribution, components drawn in a sequenced order.
#pragma once

#include <ltc/config.hpp>

#include <glm/glm.hpp>

#include <cstdint>

LTC_NAMESPACE_BEGIN
namespace ground_truth {

/// SplitMix64 (Steele, Lea and Flood 2014): a small, fast, statistically sound generator whose
/// sequence is fixed by its seed.
class splitmix64 {
  public:
    explicit splitmix64(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1).
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Uniform in [0, 1)^2 and [0, 1)^3, drawn in component order (the order in which the
    /// arguments of a constructor are evaluated is unspecified, so never write
    /// dvec2(uniform(), uniform()): GCC and Clang would draw different points).
    glm::dvec2 uniform2() {
        const double x = uniform();
        const double y = uniform();
        return {x, y};
    }
    glm::dvec3 uniform3() {
        const double x = uniform();
        const double y = uniform();
        const double z = uniform();
        return {x, y, z};
    }

  private:
    std::uint64_t state_;
};

}  // namespace ground_truth
LTC_NAMESPACE_END
