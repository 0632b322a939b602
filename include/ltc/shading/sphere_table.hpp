// ltc/shading/sphere_table.hpp -- the sphere form factor of ltc/core/sphere_form_factor.hpp as a
// 32 x 32 table: the texture that a renderer's clipless shading reads (ltc/shading/clipless.hpp,
// method::table; Hill and Heitz 2016).
//
//   #include <ltc/shading/sphere_table.hpp>
//   float I = ltc::clipless::sphere_form_factor_table(f, cos_omega);  // host: the built-in table
//   ltc::clipless::fill_sphere_table(texels);                          // the texture to upload
//
// The table stores q = I / sin^3(sigma) over t = cos(omega) / sin(sigma) in [-1, 1] and
// y = 1 - cos(sigma) in [0, 1], read bilinearly (sphere_table); outside the band I is c f or 0,
// computed exactly. Its error is at most 8.1e-3 f (derived), 2.3e-3 f in practice
// (tests/test_sphere_form_factor.cpp checks both). Conventions: f = sin^2(sigma), cos(omega) as
// in ltc/shading/clipless.hpp. The table is 4 KiB of float, built once on first use.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/sphere_form_factor.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

LTC_NAMESPACE_BEGIN
namespace clipless {

namespace detail {

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

/// Resolution of sphere_table.
constexpr std::size_t sphere_table_size = 32;

/// Writes the 32 x 32 table of q(t, y) = I / sin^3(sigma) (sphere_table) to out, row-major with
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
///
/// The table. sphere_table stores q = I / sin^3(sigma) on 32 x 32 nodes over t = cos(omega) /
/// sin(sigma) in [-1, 1] (the band, where clipping happens; outside it I is c f or 0, computed
/// exactly) and y = 1 - cos(sigma) in [0, 1], node (i, j) at t = -1 + 2 i / 31, y = j / 31, read
/// with bilinear interpolation. At y = 0 the nodes hold the limit of a small disk cut by a chord,
/// q0(t) = (t (pi/2 + t sqrt(1 - t^2) + asin t) + 2/3 (1 - t^2)^(3/2)) / pi (docs/design_notes.md:
/// why these axes rather than those of Heitz's demo code).
/// Error bound: q is C^1 on the closed square (smooth inside the band, joining c f and 0 with
/// a continuous slope at t = +-1), so in each cell bilinear interpolation errs by at most
/// h_t/4 osc(q_t) + h_y/4 osc(q_y), h_t = 2/31, h_y = 1/31, osc the oscillation of the partial
/// derivative over the cell (1D: the error e = f - interpolant has e' = f' - mean slope, so
/// |e| <= h osc(f') / 4; the tensor product adds the two directions). With the oscillations
/// evaluated cell by cell this bounds the error by 8.1e-3 sin^3(sigma) <= 8.1e-3 f; the error is
/// below 2.3e-3 f everywhere (tests/test_sphere_form_factor.cpp checks both, cell by cell). No
/// uniform bound through second derivatives exists: near t = 1, y = 1 (a hemisphere-sized sphere
/// just touching the horizon) q_tt grows like cos(sigma)^(-3/2). The table is 4 KiB of float,
/// built once on first use from the analytic formula (fill_sphere_table(), which is also what a
/// renderer uploads as a texture); nothing is generated at build time.
struct sphere_table {
    float q[sphere_table_size * sphere_table_size];

    /// sphere_form_factor(f, cos_omega) from the table: exact outside the band |cos(omega)| <
    /// sin(sigma), bilinear inside (error <= 8.1e-3 f derived, below 2.3e-3 f tested: the struct's comment).
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

}  // namespace clipless
LTC_NAMESPACE_END
