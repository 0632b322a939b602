// Helpers of the bad-input tests (test_bad_input.cpp, test_checked_factories.cpp): the
// supplement's matrix and a rounding bound for results assembled from edge terms.
#pragma once

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

}  // namespace ltc_test
