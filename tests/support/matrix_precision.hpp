// The matrices of the normalization tests (test_normalization.cpp, test_jacobian.cpp) in the
// precision under test, and that precision's machine epsilon.
#pragma once

#include <glm/glm.hpp>

#include <limits>

namespace ltc_test::precision {

template <typename T>
double eps() {
    return static_cast<double>(std::numeric_limits<T>::epsilon());
}

/// The matrix of a test in precision T, and the double matrix with exactly the same entries (the
/// reference for the float distribution is the distribution of the rounded matrix).
template <typename T>
glm::mat<3, 3, T> in_precision(const glm::dmat3& m) {
    return glm::mat<3, 3, T>(m);
}
template <typename T>
glm::dmat3 exact_matrix(const glm::dmat3& m) {
    return glm::dmat3(in_precision<T>(m));
}

}  // namespace ltc_test::precision
