// Deterministic random numbers for tests: the library's SplitMix64 (ltc/reference/ground_truth.hpp), with
// doubles in [0, 1) from the top 53 bits. Unlike std::uniform_real_distribution, the sequence is
// the same on every standard library, so a fixed seed gives the same test on every machine.
#pragma once

#include <ltc/reference/ground_truth.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace ltc_test {

class rng {
  public:
    explicit rng(std::uint64_t seed) : generator_(seed) {}

    std::uint64_t next_u64() { return generator_.next(); }
    /// Uniform in [0, 1).
    double uniform() { return generator_.uniform(); }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /// Uniform in [0, 1)^2, in the scalar type of the sampler under test (a float made from a
    /// double in [0, 1) can round up to 1: clamp to the largest float below 1).
    template <typename T>
    glm::vec<2, T> uniform2() {
        // Two statements: the order of evaluation of constructor arguments is unspecified, and
        // compilers differ, which would make the "same seed" draw different points.
        const T x = below_one<T>(uniform());
        const T y = below_one<T>(uniform());
        return glm::vec<2, T>(x, y);
    }
    /// Uniform direction on the unit sphere.
    glm::dvec3 direction() {
        const double z = 1 - 2 * uniform();
        const double phi = 2 * 3.141592653589793 * uniform();
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }

  private:
    template <typename T>
    static T below_one(double u) {
        const T t = static_cast<T>(u);
        return t < T(1) ? t : T(1) - std::numeric_limits<T>::epsilon() / 2;
    }
    ltc::ground_truth::splitmix64 generator_;
};

}  // namespace ltc_test
