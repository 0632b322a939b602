// Accurate integration over the unit sphere and the upper hemisphere, for reference values in
// tests (normalization, moments).
//
// Rule. A product rule in (z = cos theta, phi) about an arbitrary pole (a `frame`):
//   - z: Gauss-Legendre with n nodes on [0, 1] (upper hemisphere); the sphere is the union of the
//     two hemispheres, each with its own n-point rule, so that a kink or jump on the equator of the
//     frame is on the boundary of both pieces and costs no accuracy;
//   - phi: the periodic trapezoid rule with 4n equispaced nodes (the phi spacing at the equator,
//     pi / (2n), matches the theta spacing of the z rule). For a periodic analytic integrand the
//     trapezoid rule converges geometrically and is the optimal rule (Trefethen & Weideman,
//     "The exponentially convergent trapezoidal rule", SIAM Review 56, 2014); Gauss-Legendre in
//     phi would converge too, only more slowly.
// This is the usual "Gauss product rule" on the sphere (Stroud 1971). For a function analytic on
// the closed (hemi)sphere, the azimuthal averages are analytic in z, and the error falls
// geometrically in n; its rate depends on how close the integrand's complex singularities are
// (for a strongly anisotropic linear transform: on the width of the peak). Putting the pole at a
// peak helps, because the z nodes cluster at the ends of [0, 1] like equispaced nodes in theta.
//
// Error estimate. integrate() evaluates the rules of order n and 2n and returns the 2n value
// together with |Q_2n - Q_n| (the largest component for vector / matrix results). Under
// geometric convergence |Q_2n - I| << |Q_2n - Q_n| once Q_n is in the asymptotic regime, so
// the difference is a conservative bound; callers also check that it is small, so that an
// unresolved integrand cannot pass with a large "error bar". Once Q_n is converged, the
// difference is at the level of floating-point rounding of the integrand, so callers add an
// epsilon-based rounding bound.
//
// Transformed distributions. For D = transformed<D_o>(M), expectations are computed in the
// ORIGINAL space (supplement, Algorithm 1): E_D[g(w)] = E_{D_o}[g(M w_o / |M w_o|)]
// = integral over the support of D_o of D_o(w_o) g(M w_o / |M w_o|) dw_o. D_o is a polynomial
// on its support (a hemisphere whose horizon is the boundary of the domain, or the sphere), and
// w_o -> M w_o / |M w_o| is analytic for an invertible M, so the integrand is analytic on the
// closed domain and the rule converges geometrically.
#pragma once

#include <glm/glm.hpp>

#include "support/gauss_legendre.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace ltc_test {

enum class domain { sphere, upper_hemisphere };

/// Orthonormal frame (t, b, n): local (x, y, z) maps to x t + y b + z n. n is the pole of the rule.
struct frame {
    glm::dvec3 t{1, 0, 0}, b{0, 1, 0}, n{0, 0, 1};
    glm::dvec3 to_world(const glm::dvec3& v) const { return v.x * t + v.y * b + v.z * n; }
};

/// A frame whose pole is the unit vector along `pole` (any non-zero vector).
inline frame frame_from_pole(const glm::dvec3& pole) {
    frame f;
    f.n = glm::normalize(pole);
    // Branch-free orthonormal basis (Duff et al., "Building an Orthonormal Basis, Revisited",
    // JCGT 6(1), 2017).
    const double s = std::copysign(1.0, f.n.z);
    const double a = -1.0 / (s + f.n.z);
    const double bb = f.n.x * f.n.y * a;
    f.t = glm::dvec3(1.0 + s * f.n.x * f.n.x * a, s * bb, -s * f.n.x);
    f.b = glm::dvec3(bb, s + f.n.y * f.n.y * a, -f.n.y);
    return f;
}

/// Largest absolute component (the error measure of integrate()).
inline double max_abs(double x) { return std::abs(x); }
inline double max_abs(const glm::dvec3& v) {
    return std::max(std::max(std::abs(v.x), std::abs(v.y)), std::abs(v.z));
}
inline double max_abs(const glm::dmat3& m) {
    return std::max(std::max(max_abs(m[0]), max_abs(m[1])), max_abs(m[2]));
}

/// Result of integrate(): value of the order-2n rule and |Q_2n - Q_n|.
template <typename V>
struct estimate {
    V value;
    double error;
};

namespace detail {

struct node2 {
    glm::dvec3 local;  // unit direction in the frame, z >= 0
    double weight;     // includes the 2 pi / n_phi of the trapezoid rule
};

/// Nodes of the order-n rule on the upper hemisphere (z in (0, 1)), in the local frame.
inline std::vector<node2> hemisphere_nodes(std::size_t n) {
    const quadrature_rule gl = gauss_legendre(n);
    const std::size_t n_phi = 4 * n;
    const double two_pi = 6.283185307179586476925286766559;
    std::vector<node2> nodes;
    nodes.reserve(n * n_phi);
    for (std::size_t j = 0; j < n_phi; ++j) {
        const double phi = two_pi * (static_cast<double>(j) + 0.5) / static_cast<double>(n_phi);
        const double c = std::cos(phi), s = std::sin(phi);
        for (std::size_t i = 0; i < n; ++i) {
            const double z = gl.x[i];
            const double r = std::sqrt((1.0 - z) * (1.0 + z));
            nodes.push_back({glm::dvec3(r * c, r * s, z), gl.w[i] * two_pi / static_cast<double>(n_phi)});
        }
    }
    return nodes;
}

}  // namespace detail

/// The order-n rule alone: integral of f(w) dw over the domain (defined in frame fr), for f
/// returning V (double, glm::dvec3, glm::dmat3 or any type with V + V and double * V; V{} must be
/// zero).
template <typename V, typename F>
V integrate_rule(const F& f, domain d, std::size_t n, const frame& fr = frame()) {
    V sum{};
    for (const detail::node2& q : detail::hemisphere_nodes(n)) {
        V part = f(fr.to_world(q.local));
        if (d == domain::sphere) {
            const glm::dvec3 lower(q.local.x, q.local.y, -q.local.z);
            part = part + f(fr.to_world(lower));
        }
        sum = sum + q.weight * part;
    }
    return sum;
}

/// Orders n and 2n: the 2n value and |Q_2n - Q_n| (see the file comment).
template <typename V, typename F>
estimate<V> integrate(const F& f, domain d, std::size_t n, const frame& fr = frame()) {
    const V coarse = integrate_rule<V>(f, d, n, fr);
    const V fine = integrate_rule<V>(f, d, 2 * n, fr);
    return {fine, max_abs(fine + (-1.0) * coarse)};
}

/// Original distribution of the same family in double precision, e.g.
/// as_double_t<ltc::clamped_cosine<float>> = ltc::clamped_cosine<double>.
template <typename Dist>
struct as_double;
template <template <typename> class DistT, typename T>
struct as_double<DistT<T>> {
    using type = DistT<double>;
};
template <typename Dist>
using as_double_t = typename as_double<Dist>::type;

/// Support of an original distribution D_o: the upper hemisphere when D_o vanishes at -z (all
/// the hemispherical distributions of the library), the sphere otherwise.
template <typename Dist>
domain support_of() {
    using D = as_double_t<Dist>;
    return D::eval(glm::dvec3(0, 0, -1)) > 0 ? domain::sphere : domain::upper_hemisphere;
}

/// E_D[g(w)] for D = transformed<Dist>(M), integrated in the original space (file comment):
/// the integral over the support of D_o of D_o(w_o) g(M w_o / |M w_o|), in double precision,
/// orders n and 2n. With M = identity it is E_{D_o}[g].
template <typename Dist, typename V, typename G>
estimate<V> expectation(const glm::dmat3& M, const G& g, std::size_t n) {
    using D = as_double_t<Dist>;
    const auto f = [&](const glm::dvec3& wo) -> V { return D::eval(wo) * g(glm::normalize(M * wo)); };
    return integrate<V>(f, support_of<Dist>(), n);
}

/// Unit eigenvector of M M^T for its largest eigenvalue (the direction of largest stretch of M,
/// where |M^-1 w| is smallest and the Jacobian |M^-1| / |M^-1 w|^3 peaks), by power iteration.
/// Used only to place the pole of a rule: a poor direction costs convergence speed, which the
/// error estimate reports, never correctness.
inline glm::dvec3 principal_direction(const glm::dmat3& M) {
    const glm::dmat3 A = M * glm::transpose(M);
    glm::dvec3 v = glm::normalize(glm::dvec3(0.577, 0.578, 0.576));
    for (int i = 0; i < 500; ++i) v = glm::normalize(A * v);
    return v;
}

}  // namespace ltc_test
