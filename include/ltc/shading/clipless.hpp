// ltc/shading/clipless.hpp -- horizon clipping without clipping: the sphere approximation of Hill and
// Heitz 2016 ("Real-Time Area Lighting: a Journey from Research to Production", SIGGRAPH
// course; the Chinese production note of this project, section "水平面裁切").
//
//   #include <ltc/shading/clipless.hpp>
//   float e = ltc::clipless::integrate(d, vertices, n, ltc::sidedness::one_sided,
//                                      ltc::clipless::method::analytic);
//
// Instead of clipping M^-1 P to the horizon (a branchy polygon clip in a shader), compute the
// *unclipped* vector form factor F of M^-1 P (ltc::vector_form_factor), replace the polygon by
// the sphere with the same vector form factor -- a sphere of angular radius sigma around the
// unit direction u has F = sin^2(sigma) u -- and return that sphere's horizon-clipped form
// factor:
//
//   f = |F| = sin^2(sigma),   cos(omega) = u.z = +-F.z / |F|   (the sign: see "Orientation").
//
// The sphere's clipped form factor is analytic (Snyder 1996, "Area light sources for real-time
// graphics", Microsoft Research MSR-TR-96-11; reproduced in the note as I_hemisphere):
//
//   pi * I(omega, sigma) = pi cos(omega) sin^2(sigma)           omega in [0, pi/2 - sigma]
//                          pi cos(omega) sin^2(sigma) + G - H   omega in [pi/2 - sigma, pi/2]
//                          G + H                                omega in [pi/2, pi/2 + sigma]
//                          0                                    omega in [pi/2 + sigma, pi]
//   gamma = asin(cos(sigma) / sin(omega))
//   G = -2 sin(omega) cos(sigma) cos(gamma) + pi/2 - gamma + sin(gamma) cos(gamma)
//   H = cos(omega) (cos(gamma) sqrt(sin^2(sigma) - cos^2(gamma))
//                   + sin^2(sigma) asin(cos(gamma) / sin(sigma)))
//
// Domain. sigma in [0, pi/2] and omega in [0, pi]; in terms of the inputs, f in [0, 1] and
// cos(omega) in [-1, 1] (both are clamped). f <= 1 always holds for a polygon: |F| =
// max_u (1/pi) int_P w.u dw <= (1/pi) int_S2 max(0, w.u) dw = 1. The first and last branches are
// cos(omega) >= sin(sigma) (the sphere is entirely above the horizon) and cos(omega) <=
// -sin(sigma) (entirely below). In the band |cos(omega)| < sin(sigma) both inverse sines are
// defined: cos(sigma) / sin(omega) <= 1 because sin^2(omega) = 1 - cos^2(omega) > cos^2(sigma),
// and cos^2(gamma) = (sin^2(sigma) - cos^2(omega)) / sin^2(omega) <= sin^2(sigma). The four
// branches join continuously (G = H = 0 at omega = pi/2 -+ sigma, H = 0 at omega = pi/2, where
// pi I = sigma - sin(sigma) cos(sigma), the circular segment that the horizon cuts off the
// projected disk).
//
// How it is evaluated. With c = cos(omega), s = sin(sigma), A = sqrt(s^2 - c^2) and
// sin^2(omega) = 1 - c^2, the identities sin(gamma) = cos(sigma)/sin(omega), cos(gamma) =
// A/sin(omega) and sqrt(s^2 - cos^2(gamma)) = |c| cos(sigma)/sin(omega) turn G -+ H into
//
//   G -+ H = S(phi) + c^2 cos(sigma) A / (1 - c^2) - |c| s^2 psi,
//   phi = atan2(A, cos(sigma)),  psi = atan2(A, |c| cos(sigma)),  S(phi) = phi - sin phi cos phi
//
// (the sign of H folds into |c|). The note's form cancels O(sigma) terms down to an O(sigma^3)
// result, which loses everything in float for small spheres near the horizon; here every term
// is O(sigma^3) and S is evaluated by its series for small phi, so the absolute error stays a
// few ulps of sin^3(sigma) for every sigma (tests/test_clipless.cpp).
//
// The table. sphere_table stores q = I / sin^3(sigma) on 32 x 32 nodes over t = cos(omega) /
// sin(sigma) in [-1, 1] (the band, where clipping happens; outside it I is c f or 0, computed
// exactly) and y = 1 - cos(sigma) in [0, 1], node (i, j) at t = -1 + 2 i / 31, y = j / 31, read
// with bilinear interpolation. At y = 0 the nodes hold the limit of a small disk cut by a chord,
// q0(t) = (t (pi/2 + t sqrt(1 - t^2) + asin t) + 2/3 (1 - t^2)^(3/2)) / pi. Both axes were chosen
// by measurement: a table indexed like the one of Heitz's demo code (ltc_2, over cos(omega) and
// f), storing I / f, is off at 32 x 32 by up to 2.8e-2 f (the clipped band is narrower than a texel for small spheres, and I has a
// square-root singularity in f at f = 1); this one by at most 2.3e-3 f (measured).
// Error bound: q is C^1 on the closed square (smooth inside the band, joining c f and 0 with
// a continuous slope at t = +-1), so in each cell bilinear interpolation errs by at most
// h_t/4 osc(q_t) + h_y/4 osc(q_y), h_t = 2/31, h_y = 1/31, osc the oscillation of the partial
// derivative over the cell (1D: the error e = f - interpolant has e' = f' - mean slope, so
// |e| <= h osc(f') / 4; the tensor product adds the two directions). With the oscillations
// evaluated cell by cell this bounds the error by 8.1e-3 sin^3(sigma) <= 8.1e-3 f; the
// measured maximum is 2.3e-3 (tests/test_clipless.cpp checks both, cell by cell). No uniform
// bound through second derivatives exists: near t = 1, y = 1 (a hemisphere-sized sphere
// just touching the horizon) q_tt grows like cos(sigma)^(-3/2). The table is 4 KiB of float,
// built once on first use from the analytic formula (fill_sphere_table(), which is also what a
// renderer uploads as a texture); nothing is generated at build time.
//
// Orientation. The sphere forgets which side of the polygon faces the shading point (Hill
// 2016 tests the light's plane equation in the shader). Here the polygon is oriented by the
// sign of p0 . sum_i p_i x p_i+1 (Newell's normal: positive when the vertices turn clockwise
// as seen from the origin, the convention of polygon.hpp), in the space where the vertices are
// given, times the sign of |M^-1|. For a front-facing polygon F points towards it; for a
// back-facing one F is flipped before the lookup. The result is signed like every integral of
// the library (positive for a front face) and sidedness applies as usual: one_sided gives 0 for
// a back face, two_sided the same value for both faces. The polygon must be planar (true for
// any light and its image under M^-1); for non-planar input the sign test is meaningless.
//
// Where it breaks down (measured in tests/test_clipless.cpp and examples/ggx_error_report.cpp):
// the approximation is exact when the polygon and its sphere are both entirely above the
// horizon (both integrals are then F.z; the sphere is above iff cos(omega) >= sin(sigma), i.e.
// F.z >= |F|^(3/2)) or both entirely below (both 0), and for caps. Otherwise the sphere
// replaces the polygon's own clipping by a cap's: a polygon above the horizon whose sphere
// dips below it gets more than F.z (the clipped sphere integral exceeds its unclipped one), a
// polygon that dips below the horizon under a sphere that does not gets F.z instead of more,
// and a polygon straddling the horizon gets a cap's clipped share instead of its own. The
// error grows with how un-cap-like the polygon is: a polygon elongated along the horizon has a
// sphere much taller than itself, and the part above the horizon can be a thin sliver that
// no cap represents (relative errors of several hundred percent of a small value). Compact
// polygons (squares, equilateral triangles) stay within about 1.2% of |F|; 16:1 rectangles lying
// along the horizon reach 19% of |F|. After M^-1 a sharp lobe (small roughness) stretches a
// light into a large, elongated polygon, so the worst cases are low roughness with lights near
// the horizon.
#pragma once

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/core/transformed.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

namespace ltc {
namespace clipless {

/// How the horizon-clipped sphere form factor is evaluated.
enum class method { analytic, table };

namespace detail {

/// x - sin x without cancellation: its Taylor series for x <= 1/2 (the first omitted term is
/// below 1e-18 x^3 / 6), the direct difference above (relative error <= 24 eps there).
template <typename T>
LTC_HOST_DEVICE inline T x_minus_sin(T x) {
    if (x > T(0.5)) return x - std::sin(x);
    const T x2 = x * x;
    return x * x2 *
           (T(1) / T(6) -
            x2 * (T(1) / T(120) -
                  x2 * (T(1) / T(5040) -
                        x2 * (T(1) / T(362880) -
                              x2 * (T(1) / T(39916800) -
                                    x2 * (T(1) / T(6227020800.0) - x2 * (T(1) / T(1307674368000.0))))))));
}

/// Limit of sphere_form_factor(s^2, t s) / s^3 as the sphere shrinks (s -> 0): a small disk
/// cut by a chord at signed distance t from its centre, (1/pi) int_{u > -t} (t + u)
/// 2 sqrt(1 - u^2) du. Used for the table's first row.
template <typename T>
inline T small_sphere_limit(T t) {
    const T u = glm::clamp(t, T(-1), T(1));
    const T w = std::sqrt((T(1) - u) * (T(1) + u));
    const T segment = pi<T>() / T(2) + u * w + std::asin(u);
    return (u * segment + T(2) / T(3) * w * w * w) / pi<T>();
}

}  // namespace detail

/// The horizon-clipped form factor (1/pi) int_{cap, z >= 0} z dw of a spherical cap of angular
/// radius sigma around a direction at angle omega from the normal, given f = sin^2(sigma) and
/// c = cos(omega): Snyder's I_hemisphere / pi (file comment), in [0, f]. Inputs are clamped to
/// f in [0, 1], c in [-1, 1].
template <typename T>
LTC_HOST_DEVICE inline T sphere_form_factor(T f, T cos_omega) {
    const T s2 = glm::clamp(f, T(0), T(1));
    const T c = glm::clamp(cos_omega, T(-1), T(1));
    const T s = std::sqrt(s2);
    if (c >= s) return c * s2;  // entirely above the horizon (also f = 0, c >= 0)
    if (c <= -s) return T(0);   // entirely below
    const T ac = std::abs(c);
    const T cos_sigma = std::sqrt(T(1) - s2);
    const T sin2_omega = (T(1) - c) * (T(1) + c);  // > cos^2(sigma) >= 0 in the band
    const T A = ltc::detail::safe_sqrt(std::fma(-ac, ac, s2));  // sqrt(s^2 - c^2), one rounding
    const T phi = std::atan2(A, cos_sigma);
    const T psi = std::atan2(A, ac * cos_sigma);
    const T g_minus_h = detail::x_minus_sin(T(2) * phi) / T(2) + c * c * cos_sigma * A / sin2_omega -
                        ac * s2 * psi;
    const T r = (c > T(0) ? c * s2 : T(0)) + g_minus_h / pi<T>();
    return glm::clamp(r, T(0), s2);
}

/// Resolution of sphere_table.
constexpr std::size_t sphere_table_size = 32;

/// Writes the 32 x 32 table of q(t, y) = I / sin^3(sigma) (file comment) to out, row-major with
/// y along rows: out[j * 32 + i] = q(-1 + 2 i / 31, j / 31). This is the texture a renderer
/// uploads; sphere_table reads it.
template <typename T = float>
inline void fill_sphere_table(T* out) {
    constexpr std::size_t N = sphere_table_size;
    for (std::size_t j = 0; j < N; ++j) {
        const double y = double(j) / double(N - 1);  // 1 - cos(sigma)
        const double s2 = y * (2.0 - y);  // sin^2(sigma) = 1 - (1 - y)^2
        const double s = std::sqrt(s2);
        for (std::size_t i = 0; i < N; ++i) {
            const double t = -1.0 + 2.0 * double(i) / double(N - 1);
            double q;
            if (j == 0)
                q = detail::small_sphere_limit(t);
            else if (i == N - 1)
                q = 1.0;  // t = 1: I = c f = s^3
            else
                q = sphere_form_factor(s2, t * s) / (s2 * s);
            out[j * N + i] = static_cast<T>(q);
        }
    }
}

/// The tabulated sphere form factor: a 32 x 32 table over the clipped band, read bilinearly.
struct sphere_table {
    float q[sphere_table_size * sphere_table_size];

    /// sphere_form_factor(f, cos_omega) from the table: exact outside the band |cos(omega)| <
    /// sin(sigma), bilinear inside (error <= 8.1e-3 f derived, 2.3e-3 f measured: file comment).
    template <typename T>
    LTC_HOST_DEVICE T lookup(T f, T cos_omega) const {
        constexpr std::size_t N = sphere_table_size;
        const T s2 = glm::clamp(f, T(0), T(1));
        const T c = glm::clamp(cos_omega, T(-1), T(1));
        const T s = std::sqrt(s2);
        if (c >= s) return c * s2;
        if (c <= -s) return T(0);
        const T t = glm::clamp(c / s, T(-1), T(1));          // s > 0 in the band
        const T y = s2 / (T(1) + std::sqrt(T(1) - s2));      // 1 - cos(sigma), no cancellation
        const T x = (t + T(1)) * T(0.5) * T(N - 1);
        const T z = glm::clamp(y, T(0), T(1)) * T(N - 1);
        const std::size_t i = x < T(N - 2) ? static_cast<std::size_t>(x) : N - 2;
        const std::size_t j = z < T(N - 2) ? static_cast<std::size_t>(z) : N - 2;
        const T fx = x - T(i), fz = z - T(j);
        const float* r0 = q + j * N + i;
        const float* r1 = r0 + N;
        const T v0 = T(r0[0]) + fx * (T(r0[1]) - T(r0[0]));
        const T v1 = T(r1[0]) + fx * (T(r1[1]) - T(r1[0]));
        const T v = v0 + fz * (v1 - v0);
        return glm::clamp(v * s2 * s, T(0), s2);
    }

    /// The table, built on first use (thread-safe static initialization; host only).
    static const sphere_table& instance() {
        static const sphere_table table = [] {
            sphere_table t{};
            fill_sphere_table(t.q);
            return t;
        }();
        return table;
    }
};

/// sphere_form_factor(f, cos_omega) read from the default table (host only).
template <typename T>
inline T sphere_form_factor_table(T f, T cos_omega) {
    return sphere_table::instance().lookup(f, cos_omega);
}

/// The sphere that stands in for a polygon: f = sin^2(sigma) = |F| and cos(omega) = u.z with u
/// the unit direction of F, flipped for a back-facing polygon (file comment, "Orientation").
template <typename T>
struct equivalent_sphere {
    T f;          // |F|, in [0, 1]
    T cos_omega;  // cosine of the angle between the sphere's centre and the normal
    T sign;       // +1 front face, -1 back face, 0 degenerate (F = 0 or not a polygon)
};

namespace detail {

/// +1 when the planar polygon at(0..n) turns clockwise as seen from the origin (polygon.hpp's
/// positive orientation), -1 when counter-clockwise, 0 when degenerate: the sign of
/// p0 . sum p_i x p_i+1, on vertices divided by their largest coordinate (one common factor,
/// so that the polygon stays planar and nothing overflows).
template <typename T, typename VertexAt>
LTC_HOST_DEVICE inline T orientation(const VertexAt& at, std::size_t n) {
    using vec3 = glm::vec<3, T>;
    if (n < 3) return T(0);
    T scale(0);
    for (std::size_t i = 0; i < n; ++i) {
        const vec3 p = at(i);
        scale = glm::max(scale, glm::max(glm::max(std::abs(p.x), std::abs(p.y)), std::abs(p.z)));
    }
    if (!(scale > T(0))) return T(0);
    const vec3 p0 = at(0) / scale;
    vec3 normal(T(0));
    vec3 prev = at(n - 1) / scale;
    for (std::size_t i = 0; i < n; ++i) {
        const vec3 p = at(i) / scale;
        normal += glm::cross(prev - p0, p - p0);  // = sum p_i x p_i+1 over the closed loop
        prev = p;
    }
    const T d = glm::dot(p0, normal);
    return d > T(0) ? T(1) : (d < T(0) ? T(-1) : T(0));
}

template <typename T>
LTC_HOST_DEVICE inline equivalent_sphere<T> sphere_of(const glm::vec<3, T>& F, T facing) {
    const T len = glm::length(F);
    if (!(len > T(0)) || facing == T(0)) return {T(0), T(0), T(0)};
    return {glm::min(len, T(1)), glm::clamp(facing * F.z / len, T(-1), T(1)), facing};
}

/// Signed clipless integral of the clamped cosine over M^-1 P, P given by at(i) in the local
/// frame, M^-1 = m_inv; Policy evaluates the edge terms of the vector form factor.
template <typename T, typename Policy, typename VertexAt>
LTC_HOST_DEVICE inline T integrate_signed(const glm::mat<3, 3, T>& m_inv, T det_inv, const VertexAt& at,
                                          std::size_t n, method how, const sphere_table* table) {
    using vec3 = glm::vec<3, T>;
    const T facing = orientation<T>(at, n);  // orientation of P
    if (facing == T(0)) return T(0);
    const auto transformed_at = [&](std::size_t i) {
        const vec3 p = at(i);
        const T s = glm::max(glm::max(std::abs(p.x), std::abs(p.y)), std::abs(p.z));
        // Unit vectors: every edge policy but exact assumes them.
        return s > T(0) ? ltc::detail::safe_normalize(m_inv * (p / s)) : vec3(T(0));
    };
    const vec3 F = ltc::detail::vector_form_factor<T, Policy>(transformed_at, n);
    const T facing_ltc = det_inv < T(0) ? -facing : facing;  // orientation of M^-1 P
    const equivalent_sphere<T> sph = sphere_of(F, facing_ltc);
    if (sph.sign == T(0)) return T(0);
    const T I = how == method::table && table ? table->lookup(sph.f, sph.cos_omega)
                                              : sphere_form_factor(sph.f, sph.cos_omega);
    return facing * I;
}

}  // namespace detail

/// The equivalent sphere of a polygon (no transformation): its unclipped vector form factor
/// and its orientation.
template <typename T>
LTC_HOST_DEVICE inline equivalent_sphere<T> sphere_of_polygon(const glm::vec<3, T>* vertices, std::size_t n) {
    const auto at = [&](std::size_t i) { return glm::vec<3, T>(vertices[i]); };
    return detail::sphere_of(ltc::vector_form_factor(vertices, n), detail::orientation<T>(at, n));
}

/// Clipless approximation of form_factor_signed (the polygon's clipped cosine integral):
/// signed by the polygon's orientation.
template <typename T>
inline T form_factor_signed(const glm::vec<3, T>* vertices, std::size_t n, method how = method::analytic) {
    const auto at = [&](std::size_t i) { return glm::vec<3, T>(vertices[i]); };
    const sphere_table* table = how == method::table ? &sphere_table::instance() : nullptr;
    return detail::integrate_signed<T, edge_policy::exact>(glm::mat<3, 3, T>(T(1)), T(1), at, n, how, table);
}

/// Clipless approximation of ltc::form_factor.
template <typename T>
inline T form_factor(const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                     method how = method::analytic) {
    return apply_sidedness(form_factor_signed(vertices, n, how), side);
}

/// Clipless approximation of d.integrate_signed(vertices, n): the unclipped vector form factor
/// of M^-1 P, its equivalent sphere, and the sphere's horizon-clipped form factor. The edge
/// terms of the vector form factor use the distribution's edge policy.
template <typename T, typename Policy>
inline T integrate_signed(const transformed<clamped_cosine<T, Policy>>& d, const glm::vec<3, T>* vertices,
                          std::size_t n, method how = method::analytic) {
    const auto at = [&](std::size_t i) { return glm::vec<3, T>(vertices[i]); };
    const sphere_table* table = how == method::table ? &sphere_table::instance() : nullptr;
    return detail::integrate_signed<T, Policy>(d.inverse_matrix(), d.inverse_determinant(), at, n, how, table);
}

/// Clipless approximation of d.integrate(vertices, n, side).
template <typename T, typename Policy>
inline T integrate(const transformed<clamped_cosine<T, Policy>>& d, const glm::vec<3, T>* vertices, std::size_t n,
                   sidedness side, method how = method::analytic) {
    return apply_sidedness(integrate_signed(d, vertices, n, how), side);
}

}  // namespace clipless
}  // namespace ltc
