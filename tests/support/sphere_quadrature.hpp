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

namespace sphere_quadrature_detail {

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

}  // namespace sphere_quadrature_detail

/// The order-n rule alone: integral of f(w) dw over the domain (defined in frame fr), for f
/// returning V (double, glm::dvec3, glm::dmat3 or any type with V + V and double * V; V{} must be
/// zero).
template <typename V, typename F>
V integrate_rule(const F& f, domain d, std::size_t n, const frame& fr = frame()) {
    // Two-level summation (each phi column, then the columns): the rounding error of the sum
    // grows like (n + 4n) eps instead of 4 n^2 eps.
    const std::vector<sphere_quadrature_detail::node2> nodes = sphere_quadrature_detail::hemisphere_nodes(n);
    V sum{};
    for (std::size_t j = 0; j < nodes.size(); j += n) {
        V column{};
        for (std::size_t i = j; i < j + n; ++i) {
            const sphere_quadrature_detail::node2& q = nodes[i];
            V part = f(fr.to_world(q.local));
            if (d == domain::sphere) {
                const glm::dvec3 lower(q.local.x, q.local.y, -q.local.z);
                part = part + f(fr.to_world(lower));
            }
            column = column + q.weight * part;
        }
        sum = sum + column;
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
// Any further parameters (clamped_cosine's edge policy) carried over: a template template
// parameter of one type matches them only with GCC's relaxed matching, not Clang's.
template <template <typename, typename...> class DistT, typename T, typename... Rest>
struct as_double<DistT<T, Rest...>> {
    using type = DistT<double, Rest...>;
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

/// Unit eigenvector of A A^T for its largest eigenvalue (the direction of largest stretch of
/// A), by power iteration. Used only to place the pole of a rule: a poor direction costs
/// convergence speed, which the error estimate reports, never correctness.
inline glm::dvec3 principal_direction(const glm::dmat3& A) {
    const glm::dmat3 AAt = A * glm::transpose(A);
    glm::dvec3 v = glm::normalize(glm::dvec3(0.577, 0.578, 0.576));
    for (int i = 0; i < 500; ++i) v = glm::normalize(AAt * v);
    return v;
}

/// A rule for integrating D = transformed<D_o>(M) itself (not an expectation in the original
/// space) over its support in the TRANSFORMED space, as supplement 2.2 does, placed where it
/// converges geometrically. Measured in double for the test matrices and the four D_o:
/// |Q_n - 1| <= 4e-9 at n = 64 and <= 2e-15 from n = 128 on; with the pole at z instead, the
/// clamped cosine's kink (on a tilted great circle) leaves algebraic convergence, e.g.
/// |Q_512 - 1| = 2e-6 for the supplement's M. The choice:
///   - hemispherical D_o: D vanishes outside the hemisphere (M^-1 w).z >= 0 = {w . M^-T z >= 0},
///     and has a kink (clamped cosine) or a jump (uniform hemisphere) on its boundary. The pole
///     is M^-T z and the domain the upper hemisphere of that frame: the kink is on the boundary
///     of the domain and D is analytic on the closed domain;
///   - uniform sphere: D = |M^-1| / (4 pi |M^-1 w|^3) is analytic on the sphere with two
///     antipodal peaks along the largest stretch of M. The pole is the direction of least
///     stretch (principal direction of M^-T), which puts both peaks on the equator, where the
///     Gauss-Legendre nodes of the two hemispheres cluster.
struct transformed_rule {
    domain d;
    frame fr;
};
inline transformed_rule transformed_space_rule(const glm::dmat3& M, domain support) {
    const glm::dmat3 inv_t = glm::transpose(glm::inverse(M));
    if (support == domain::upper_hemisphere)
        return {domain::upper_hemisphere, frame_from_pole(inv_t * glm::dvec3(0, 0, 1))};
    return {domain::sphere, frame_from_pole(principal_direction(inv_t))};
}

// ---------------------------------------------------------------------------------------------
// Shared fixtures of the normalization and sampling tests.

/// The linear transforms under test (GLM is column-major: a matrix printed row-major as
/// [a b c; d e f; g h i] is glm::transpose(glm::dmat3(a, b, c, d, e, f, g, h, i))).
struct named_matrix {
    const char* name;
    glm::dmat3 m;
};

inline glm::dmat3 row_major_matrix(double a, double b, double c, double d, double e, double f,
                                   double g, double h, double i) {
    return glm::transpose(glm::dmat3(a, b, c, d, e, f, g, h, i));
}

inline std::vector<named_matrix> test_matrices() {
    const double c1 = std::cos(0.7), s1 = std::sin(0.7), c2 = std::cos(1.1), s2 = std::sin(1.1);
    const glm::dmat3 rz = row_major_matrix(c1, -s1, 0, s1, c1, 0, 0, 0, 1);
    const glm::dmat3 rx = row_major_matrix(1, 0, 0, 0, c2, -s2, 0, s2, c2);
    return {
        {"identity", glm::dmat3(1.0)},
        // supplement section 2.3: M = [0.1 0.5 1; 0.2 1 1; 0 2 0.5], det = 0.2
        {"supplement", row_major_matrix(0.1, 0.5, 1, 0.2, 1, 1, 0, 2, 0.5)},
        // a rotation Rz(0.7) Rx(1.1): D is D_o rotated
        {"rotation", rz * rx},
        // GGX-like fit [a 0 b; 0 c 0; d 0 1], a = c = 0.1, b = 0.05, d = -0.2: a narrow lobe
        {"anisotropic", row_major_matrix(0.1, 0, 0.05, 0, 0.1, 0, -0.2, 0, 1)},
        // det = -0.246: orientation-reversing
        {"negative det", row_major_matrix(0.5, 0.2, 0.3, -0.3, -0.9, 0.1, 0.4, -0.2, 1.0)},
    };
}

/// kappa_F(M) = |M|_F |M^-1|_F >= the 2-norm condition number; used in rounding bounds.
inline double frobenius_condition(const glm::dmat3& M) {
    const auto fro = [](const glm::dmat3& a) {
        return std::sqrt(glm::dot(a[0], a[0]) + glm::dot(a[1], a[1]) + glm::dot(a[2], a[2]));
    };
    return fro(M) * fro(glm::inverse(M));
}

/// The cube map: the sphere partitioned by the central projection of the 6 faces of the cube
/// [-1, 1]^3, each face cut into k x k square cells. Face f = 2 axis + (sign < 0); on face
/// (a, s) the point is s e_a + u e_b + v e_c, (a, b, c) cyclic, u, v in [-1, 1].
struct cube_map {
    int k;

    int cells() const { return 6 * k * k; }

    /// Cell (face, i, j) covers u in [-1 + 2i/k, -1 + 2(i+1)/k], v likewise with j. Vertices in
    /// the order that makes the polygon's right-hand normal point away from the origin (the
    /// positive orientation of ltc's signed integrals): counter-clockwise seen from outside.
    std::vector<glm::dvec3> cell_quad(int cell) const {
        const int face = cell / (k * k), i = (cell / k) % k, j = cell % k;
        const int a = face / 2, b = (a + 1) % 3, c = (a + 2) % 3;
        const double s = face % 2 ? -1.0 : 1.0;
        const auto corner = [&](int ii, int jj) {
            glm::dvec3 p(0);
            p[a] = s;
            p[b] = -1.0 + 2.0 * ii / k;
            p[c] = -1.0 + 2.0 * jj / k;
            return p;
        };
        std::vector<glm::dvec3> q = {corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1)};
        if (s < 0) std::swap(q[1], q[3]);  // reverses the orientation
        return q;
    }

    /// The cell that contains direction w (w != 0). Ties on cell boundaries (a set of measure
    /// zero) go to the first axis / the higher cell.
    int cell_of(const glm::dvec3& w) const {
        const glm::dvec3 aw = glm::abs(w);
        const int a = aw.x >= aw.y && aw.x >= aw.z ? 0 : (aw.y >= aw.z ? 1 : 2);
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const int face = 2 * a + (w[a] < 0 ? 1 : 0);
        const auto index = [&](double t) {  // t in [-1, 1]
            const int x = static_cast<int>(std::floor((t + 1.0) * 0.5 * k));
            return std::min(std::max(x, 0), k - 1);
        };
        return face * k * k + index(w[b] / aw[a]) * k + index(w[c] / aw[a]);
    }
};

}  // namespace ltc_test
