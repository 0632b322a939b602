// Shared pieces of the polygon-integration tests (test_polygon_integration.cpp,
// test_transformed_integration.cpp, test_polygon_conventions.cpp, test_polygon_cube.cpp): the
// four original densities written from their definitions, small polygon helpers, the closed
// forms under test by distribution id, and the test matrices.
#pragma once

#include <ltc/ltc.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace ltc_test::polygon_integration {

using glm::dmat3;
using glm::dvec3;
using poly_t = std::vector<dvec3>;

inline constexpr double kPi = 3.141592653589793238462643383279502884;

// ---------------------------------------------------------------------------------------------
// Reference densities in double, written from their definitions (supplement section 1); the
// library is never called to build a reference.

enum dist_id { sphere = 0, hemisphere = 1, cosine = 2, squared = 3 };
inline const char* const dist_names[4] = {"uniform_sphere", "uniform_hemisphere", "clamped_cosine", "squared_clamped_cosine"};

/// The four D_o at a direction of height z (they depend on z only).
inline std::array<double, 4> reference_densities_z(double z_signed) {
    const double z = std::max(0.0, z_signed);
    return {1 / (4 * kPi), z_signed >= 0 ? 1 / (2 * kPi) : 0.0, z / kPi, 3 * z * z / (2 * kPi)};
}

/// Integrand for the brute force with h = (0, 0, 1): s = w.z, given accurately.
inline std::array<double, 4> reference_densities(const dvec3&, double s) { return reference_densities_z(s); }

inline std::string str(const poly_t& p) {
    std::ostringstream s;
    s << std::setprecision(17) << "{";
    for (const dvec3& v : p) s << " (" << v.x << ", " << v.y << ", " << v.z << ")";
    s << " }";
    return s.str();
}

inline std::string str(const dmat3& m) {  // row-major, as the paper prints matrices
    std::ostringstream s;
    s << std::setprecision(17) << "[";
    for (int r = 0; r < 3; ++r) s << (r ? "; " : "") << m[0][r] << " " << m[1][r] << " " << m[2][r];
    s << "]";
    return s.str();
}

template <typename T>
std::vector<glm::vec<3, T>> to(const poly_t& p) {
    std::vector<glm::vec<3, T>> v;
    for (const dvec3& x : p) v.push_back(glm::vec<3, T>(x));
    return v;
}

inline poly_t reversed(poly_t p) {
    std::reverse(p.begin(), p.end());
    return p;
}

inline poly_t transform(const dmat3& m, const poly_t& p) {
    poly_t q;
    for (const dvec3& x : p) q.push_back(m * x);
    return q;
}

/// The paper's row-major 3x3 matrix as a GLM (column-major) matrix, rounded to float so that the
/// float and double tests see the same, exactly representable, M.
inline dmat3 row_major(double a, double b, double c, double d, double e, double f, double g, double h, double i) {
    return dmat3(glm::mat3(glm::transpose(dmat3(a, b, c, d, e, f, g, h, i))));
}

// ---------------------------------------------------------------------------------------------
// Closed forms under test, by distribution id.

template <typename T>
T closed_form(int id, const poly_t& p) {
    const auto v = to<T>(p);
    switch (id) {
        case sphere: return ltc::uniform_sphere<T>::integrate(v.data(), v.size());
        case hemisphere: return ltc::uniform_hemisphere<T>::integrate(v.data(), v.size());
        case cosine: return ltc::clamped_cosine<T>::integrate(v.data(), v.size());
        default: return ltc::squared_clamped_cosine<T>::integrate(v.data(), v.size());
    }
}

template <typename T>
T closed_form_signed(int id, const poly_t& p) {
    const auto v = to<T>(p);
    const glm::vec<3, T>* d = v.data();
    switch (id) {
        case sphere: return ltc::uniform_sphere<T>::signed_integral(d, v.size());
        case hemisphere: return ltc::uniform_hemisphere<T>::signed_integral(d, v.size());
        case cosine: return ltc::clamped_cosine<T>::signed_integral(d, v.size());
        default: return ltc::squared_clamped_cosine<T>::signed_integral(d, v.size());
    }
}

// ---------------------------------------------------------------------------------------------
// Test matrices of the transformed distributions.

struct named_matrix {
    const char* name;
    dmat3 m;  // GLM column-major, entries exactly representable in float
};

inline std::vector<named_matrix> test_matrices() {
    // rotation by 1 rad about (1, 2, 3) / |(1, 2, 3)| (Rodrigues), written column-major
    const dvec3 k = glm::normalize(dvec3(1, 2, 3));
    const double c = std::cos(1.0), s = std::sin(1.0);
    const dmat3 kx(0, k.z, -k.y, -k.z, 0, k.x, k.y, -k.x, 0);  // columns of [k]_x
    const dmat3 rot = dmat3(1) * c + kx * s + glm::outerProduct(k, k) * (1 - c);
    return {
        // The supplement's example, printed row-major: M = [0.1 0.5 1; 0.2 1 1; 0 2 0.5].
        {"supplement", row_major(0.1, 0.5, 1, 0.2, 1, 1, 0, 2, 0.5)},
        {"rotation", dmat3(glm::mat3(rot))},
        {"near-identity", row_major(1.001, 0.0005, -0.0007, -0.0003, 0.9992, 0.0004, 0.0006, -0.0002, 1.0009)},
        // GGX-like fit matrix [a 0 b; 0 c 0; d 0 1] of a rough-to-sharp lobe
        {"ggx-like", row_major(0.05, 0, -0.02, 0, 0.05, 0, 0.3, 0, 1)},
        {"anisotropic", row_major(0.2, 0, 0.1, 0, 0.6, 0, -0.4, 0, 1)},
        // det < 0 (about -0.991): M flips orientations
        {"negative-det", row_major(1, 0.2, 0.1, 0.3, -0.7, 0.2, -0.1, 0.4, 1.2)},
    };
}

}  // namespace ltc_test::polygon_integration
