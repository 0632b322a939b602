// ltc/core/spherical_polygon_sampling.hpp -- uniform sampling in solid angle of a convex planar
// polygon seen from the origin, as a sampler trio (sample / pdf / invert) for host and device
// code (fixed capacity, no heap, no exceptions), in float or double: a fan of triangles, each
// sampled by Arvo's method (ltc/core/spherical_triangle_sampling.hpp).
//
//   const ltc::spherical_polygon_sampler<float> s(vertices, n);   // n <= max_vertices (8), any scale and winding
//   glm::vec3 w = s.sample(u);    // u in [0, 1)^2; density s.pdf(w) = 1 / s.solid_angle() inside
//   glm::vec2 v = s.invert(w);    // v == u up to rounding
//
// Precondition: the polygon is convex and planar, and its plane misses the origin (a polygon
// light seen from a shading point in front of or behind it). The spherical polygon is then convex
// and lies in an open hemisphere. (Non-convex polygons: ltc::ground_truth::spherical_polygon.)
// Degenerate cases: n < 3, n > max_vertices, a vertex at the origin, non-finite vertices or zero
// solid angle give an empty() sampler (pdf() 0).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/solid_angle.hpp>  // triangle_solid_angle
#include <ltc/core/spherical_triangle_sampling.hpp>
#include <ltc/core/detail/polygon_check.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/detail/wider.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <type_traits>

LTC_NAMESPACE_BEGIN

namespace detail {
/// Stands in for the wide sampler when Wide is T itself (never used).
struct no_wide_sampler {};
}  // namespace detail

/// Uniform sampling in solid angle of a convex planar polygon of at most MaxVertices vertices,
/// seen from the origin, rebuilt in Wide where T's rounding of the unit vertices would move its
/// solid angle by more than 2^-12 (Wide = T opts out).
///
/// Accuracy. The unit vertices in T are each off by ~epsilon, which moves the solid angle of a
/// fan triangle by ~epsilon times its perimeter: relative to the solid angle, epsilon / h for a
/// polygon of size h (or a sliver of width h). Where the fan's perimeter times epsilon exceeds
/// 2^-12 of the solid angle (in float: polygons under ~2e-3 rad across, slivers under ~1e-3 rad
/// wide), the sampler is rebuilt in the wider type Wide (double for float; Wide = T opts out,
/// e.g. on a GPU) from the input vertices, converted exactly and normalized in Wide: sample() and
/// invert() run in Wide, and solid_angle() is the rounding to T of the value in Wide (for polygons
/// of the size Wide resolves). pdf() is 1 / solid_angle() inside the great circles of the edges,
/// with a margin of the samples' rounding (pdf()), so that no sample has pdf 0.
template <typename T, std::size_t MaxVertices = 8, typename Wide = detail::wider_t<T>>
class spherical_polygon_sampler {
    static_assert(MaxVertices >= 3, "a polygon has at least 3 vertices");
    template <typename, std::size_t, typename>
    friend class spherical_polygon_sampler;  // the wide one's vertices and normals

  public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;
    /// The capacity: the most vertices a polygon may have, the MaxVertices template argument (a
    /// larger one holds larger polygons). n <= max_vertices is a precondition of the constructor,
    /// which gives an empty() sampler above it (it cannot throw: device code); checked() throws.
    static constexpr std::size_t max_vertices = MaxVertices;

    /// An empty sampler.
    LTC_HOST_DEVICE spherical_polygon_sampler() = default;

    /// vertices[0..n): a convex planar polygon (any scale, either winding) whose plane misses the
    /// origin. n < 3, n > max_vertices, a vertex at the origin, non-finite vertices or zero solid
    /// angle (the polygon seen edge-on) give an empty sampler.
    LTC_HOST_DEVICE spherical_polygon_sampler(const vec3* vertices, std::size_t n) {
        if (n < 3 || n > MaxVertices) return;
        for (std::size_t i = 0; i < n; ++i) {
            v_[i] = detail::safe_normalize(vertices[i]);
            if (v_[i] == vec3(T(0)) || !detail::is_finite(v_[i])) return;  // at the origin: seen edge-on
        }
        // Orientation from the signed total (ltc::solid_angle's fan); a fan triangle of the other
        // orientation can only come from rounding (collinear vertices) and is never sampled.
        T omega[MaxVertices - 2]{};
        T signed_total = T(0);
        for (std::size_t k = 1; k + 1 < n; ++k)
            signed_total += omega[k - 1] = triangle_solid_angle(v_[0], v_[k], v_[k + 1]);
        if (!(std::abs(signed_total) > T(0)) || !std::isfinite(signed_total)) return;
        const T s = signed_total > T(0) ? T(1) : T(-1);
        T acc = T(0);
        for (std::size_t k = 1; k + 1 < n; ++k) {
            if (s * omega[k - 1] > T(0)) tri_[k - 1] = spherical_triangle_sampler<T>(v_[k], v_[0], v_[k + 1]);
            acc += tri_[k - 1].solid_angle();
            cdf_[k - 1] = acc;
        }
        for (std::size_t i = 0; i < n; ++i) {
            const vec3& a = v_[i];
            const vec3& b = v_[i + 1 < n ? i + 1 : 0];
            n_[i] = s * detail::stable_cross(a, b, glm::dot(a, b));
        }
        n_vertices_ = n;
        orientation_ = s;
        total_ = acc;
        if constexpr (widens) {
            // epsilon P > 2^-12 Omega, with P^2 <= k sum d^2 (fan_chords), squared: no square root.
            // fan_chords() <= 4 k^2 (chords <= 2): polygons above that bound skip it.
            const T e = detail::epsilon<T>(), omega = T(1.0 / 4096) * total_;
            const T k = T(3 * n_vertices_ - 6);
            if (T(4) * k * k * e * e > omega * omega && e * e * fan_chords() > omega * omega) widen(vertices);
        }
    }

    /// Like the constructor, but throws ltc::invalid_polygon (ltc/core/invalid_polygon.hpp) for
    /// n > max_vertices, n < 3 or a vertex not finite: input that is no polygon it can hold. (A
    /// polygon seen edge-on still gives an empty() sampler.)
    static spherical_polygon_sampler checked(const vec3* vertices, std::size_t n) {
        detail::require_polygon("ltc::spherical_polygon_sampler", vertices, n, max_vertices);
        return spherical_polygon_sampler(vertices, n);
    }

    /// Solid angle of the polygon (the sum of its fan triangles'); 0 when empty().
    LTC_HOST_DEVICE T solid_angle() const { return total_; }
    /// Whether the polygon is sampled in Wide (the class comment's Accuracy).
    LTC_HOST_DEVICE bool widened() const { return widened_; }
    /// No direction to sample (constructor); then sample() returns a finite unit direction (the
    /// first vertex when it is one) and pdf() is 0.
    LTC_HOST_DEVICE bool empty() const { return !(total_ > T(0)); }

    /// A direction uniformly distributed in the polygon for u in [0, 1]^2.
    ///
    /// The polygon is a fan of triangles around vertex 0 (v_0, v_k, v_k+1), k = 1 .. n-2, each
    /// sampled by Arvo's method (ltc/core/spherical_triangle_sampling.hpp) as
    /// (a, b, c) = (v_k, v_0, v_k+1): then u.x = 0 is the edge v_0 v_1, u.x = 1 the edge v_n-1 v_0,
    /// the diagonal v_0 v_k+1 is where triangle k ends and k+1 begins, and u.y = 0 is v_0; u.x
    /// picks triangle k with probability Omega_k / Omega (Van Oosterom and Strackee 1983) and is
    /// rescaled into [0, 1] for it, so the mapping [0, 1)^2 -> polygon is continuous and one 2D
    /// sample keeps its stratification.
    LTC_HOST_DEVICE vec3 sample(const vec2& u) const {
        if (empty()) return v_[0] == vec3(T(0)) || !detail::is_finite(v_[0]) ? vec3(T(0), T(0), T(1)) : v_[0];
        if constexpr (widens) {
            if (widened_) return sample_wide(u);
        }
        const T target = u.x * total_;
        // The first triangle whose cdf step passes target (empty triangles have flat steps); the
        // last non-empty one when rounding puts target at or above the total.
        std::size_t k = 0, last = 0;
        bool found = false;
        for (std::size_t i = 0; i + 2 < n_vertices_; ++i) {
            if (tri_[i].empty()) continue;
            last = i;
            if (!found && target < cdf_[i]) {
                k = i;
                found = true;
            }
        }
        if (!found) k = last;
        const T below = k > 0 ? cdf_[k - 1] : T(0);
        const T ux = glm::clamp((target - below) / tri_[k].solid_angle(), T(0), T(1));
        return tri_[k].sample(vec2(ux, u.y));
    }

    /// 1 / solid_angle() for unit w on the inner side of the great circles of all edges (the
    /// polygon is convex), 0 elsewhere and when empty(). Every sample has pdf > 0: w counts as
    /// inside an edge (a, b) also when outside its great circle by at most
    /// detail::sample_margin<T>() (the rounding of sample() and of this test) and on the side of
    /// the arc a b, w.(a + b) > 0 (without that, the antipodes of a polygon narrower than the
    /// margin would be inside too).
    LTC_HOST_DEVICE T pdf(const vec3& w) const {
        if (empty()) return T(0);
        for (std::size_t i = 0; i < n_vertices_; ++i) {
            const T d = glm::dot(w, n_[i]);
            if (d < T(0)) return pdf_near_boundary(w, d, i);
        }
        return T(1) / total_;
    }

    /// The u in [0, 1]^2 that sample() maps to the unit direction w (u = 0 when empty(); for w
    /// outside, the u of a nearby point of the polygon).
    LTC_HOST_DEVICE vec2 invert(const vec3& w) const {
        if (empty()) return vec2(T(0));
        if constexpr (widens) {
            if (widened_) return vec2(wide_.sampler.invert(glm::vec<3, Wide>(w)));
        }
        // The fan triangle of w: the last non-empty (v_0, v_k, v_k+1) with w past its first side
        // v_0 v_k (the polygon is convex: w is past the diagonals through v_0 up to its own
        // triangle's). A point on a diagonal maps to the same u from either side.
        std::size_t k = 0;
        bool first = true;
        for (std::size_t i = 0; i + 2 < n_vertices_; ++i) {
            if (tri_[i].empty()) continue;
            if (first || past_diagonal(w, i + 1)) k = i;
            first = false;
        }
        const vec2 ut = tri_[k].invert(w);
        const T below = k > 0 ? cdf_[k - 1] : T(0);
        return vec2(glm::clamp((below + ut.x * tri_[k].solid_angle()) / total_, T(0), T(1)), ut.y);
    }

  private:
    static constexpr bool widens = !std::is_same_v<T, Wide>;

    /// k sum d^2 over the k chords d of the fan triangles' perimeters (the edges, and each
    /// diagonal twice): at least P^2, P the sum of the perimeters (Cauchy-Schwarz), and within a
    /// factor k of it. Each unit vertex is within 2 u of its exact direction (u = epsilon / 2),
    /// which moves a triangle's solid angle by up to 2 u times its perimeter (first order): with
    /// the formulas' few u, T's relative error of the pdf and of the triangles' probabilities is
    /// about u P / solid_angle().
    LTC_HOST_DEVICE T fan_chords() const {
        T sum = T(0);
        for (std::size_t i = 0; i < n_vertices_; ++i) {
            const vec3 d = v_[i + 1 < n_vertices_ ? i + 1 : 0] - v_[i];
            sum += glm::dot(d, d);
        }
        for (std::size_t k = 2; k + 1 < n_vertices_; ++k) {  // the diagonals
            const vec3 d = v_[k] - v_[0];
            sum += T(2) * glm::dot(d, d);
        }
        return T(3 * n_vertices_ - 6) * sum;  // k = n + 2 (n - 3)
    }

    /// The polygon once more in Wide, from the input vertices (converted exactly, normalized in
    /// Wide): sample() and invert() go through it, and pdf() tests its unit vertices and normals
    /// rounded to T (within u of them, far inside the margin). Kept in T when Wide finds it empty.
    LTC_HOST_DEVICE LTC_NOINLINE void widen(const vec3* vertices) {
        glm::vec<3, Wide> in[MaxVertices];
        for (std::size_t i = 0; i < n_vertices_; ++i) in[i] = glm::vec<3, Wide>(vertices[i]);
        wide_.sampler = wide_sampler(in, n_vertices_);  // trivial assignment: begins its lifetime
        const wide_sampler& w = wide_.sampler;
        const T total = T(w.total_);
        if (w.empty() || !(total > T(0)) || !std::isfinite(total)) return;
        for (std::size_t i = 0; i < n_vertices_; ++i) {
            v_[i] = vec3(w.v_[i]);
            n_[i] = vec3(w.n_[i]);
        }
        total_ = total;
        widened_ = true;
    }

    /// pdf() for w outside the great circle of edge i, d = w.n_i < 0: 0 beyond the margin, else the
    /// test with the margin on all edges; out of pdf()'s line.
    LTC_HOST_DEVICE LTC_NOINLINE T pdf_near_boundary(const vec3& w, T d, std::size_t i) const {
        const T m = detail::sample_margin<T>();
        if (d * d > m * m * glm::dot(n_[i], n_[i])) return T(0);
        for (std::size_t j = 0; j < n_vertices_; ++j)
            if (!detail::inside_edge(w, n_[j], v_[j], v_[j + 1 < n_vertices_ ? j + 1 : 0])) return T(0);
        return T(1) / total_;
    }

    /// sample() in Wide, out of sample()'s line. A unit vector in Wide rounded to T: unit within u,
    /// and within u of the wide sample.
    LTC_HOST_DEVICE LTC_NOINLINE vec3 sample_wide(const vec2& u) const {
        if constexpr (widens) return vec3(wide_.sampler.sample(glm::vec<2, Wide>(u)));
        else return vec3(T(0));
    }

    /// w on the side of the great circle through v_0 and v_i where v_i+1 is: the sign of
    /// w.(v_0 x v_i) is that of v_i+1.(v_0 x v_i) = v_0.(v_i x v_i+1), the orientation.
    LTC_HOST_DEVICE bool past_diagonal(const vec3& w, std::size_t i) const {
        return orientation_ * glm::dot(w, detail::stable_cross(v_[0], v_[i], glm::dot(v_[0], v_[i]))) >= T(0);
    }

    vec3 v_[MaxVertices]{};                                 // unit vertices
    vec3 n_[MaxVertices]{};                                 // inward normals of the edges' great circles
    spherical_triangle_sampler<T> tri_[MaxVertices - 2]{};  // (v_k, v_0, v_k+1), empty if not sampled
    T cdf_[MaxVertices - 2]{};                              // running sums of their solid angles
    T total_ = T(0), orientation_ = T(0);                   // solid angle; sign of the signed one
    std::size_t n_vertices_ = 0;
    bool widened_ = false;
    using wide_sampler =
        std::conditional_t<widens, spherical_polygon_sampler<Wide, MaxVertices, Wide>, detail::no_wide_sampler>;
    /// The wide sampler, written by widen() and read only when widened_: not zeroed (it is most
    /// of the sampler's size) for the polygons that never widen.
    union wide_storage {
        char none;
        wide_sampler sampler;
        LTC_HOST_DEVICE wide_storage() : none(0) {}
    };
    wide_storage wide_;
};

LTC_NAMESPACE_END
