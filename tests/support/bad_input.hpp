// Helpers of the bad-input tests (test_bad_input.cpp, test_checked_factories.cpp, and the
// two-lobe tables' tests): the supplement's matrix, a rounding bound for results assembled from
// edge terms, and the degenerate lights every polygon-light shading gives 0 for.
#pragma once

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include <cstddef>
#include <limits>

namespace ltc_test {

/// The matrix of the paper's supplemental validation session (printed row-major there).
template <typename T>
glm::mat<3, 3, T> supplement_m() {
    return glm::transpose(glm::mat<3, 3, T>(0.1, 0.5, 1, 0.2, 1, 1, 0, 2, 0.5));
}

// Relative rounding bound for a result assembled from n edge terms of ~20 operations each,
// with the sum's absolute error scaled by sum|term| <= n * pi / (2 pi) (derivation in the test
// of each use): u * (20 + n) * n / 2.
template <typename T>
T edge_sum_bound(std::size_t n) {
    return std::numeric_limits<T>::epsilon() / 2 * T(20 + n) * T(n) / 2;
}

/// A polygon-light shading gives exactly 0 for n < 3, for N = 0 and for a vertex at the shading
/// point: `shade(N, vertices, n)` shades at the origin (its other arguments fixed by the caller),
/// `quad` a light of 4 vertices, `N` a valid normal.
template <typename Shade>
void check_degenerate_lights_give_zero(const glm::dvec3* quad, const glm::dvec3& N, Shade&& shade) {
    const glm::dvec3 at_p[4] = {glm::dvec3(0), quad[1], quad[2], quad[3]};
    for (const auto& r : {shade(N, quad, 2), shade(glm::dvec3(0), quad, 4), shade(N, at_p, 4)}) {
        CHECK(r.specular == glm::dvec3(0));
        CHECK(r.diffuse == glm::dvec3(0));
    }
}

}  // namespace ltc_test
