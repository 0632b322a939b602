// ltc/core/spherical_triangle_sampling.hpp -- uniform sampling of a spherical triangle in solid
// angle, as a sampler trio (sample / pdf / invert) for host and device code (no heap, no
// exceptions), in float or double: Arvo's mapping (J. Arvo, "Stratified sampling of spherical
// triangles", SIGGRAPH 1995) in pbrt-v4's arrangement, its sub-triangle found in closed form.
//
//   const ltc::spherical_triangle_sampler<float> s(a, b, c);   // unit vectors, either orientation
//   glm::vec3 w = s.sample(u);    // u in [0, 1)^2; density s.pdf(w) = 1 / s.solid_angle() inside
//   glm::vec2 v = s.invert(w);    // v == u up to rounding
//
// Conventions: the triangle lies in an open hemisphere (as the projection of any planar triangle
// that misses the origin does). Degenerate cases: coincident or collinear vertices, or non-finite
// input, give an empty() sampler (solid angle 0, pdf() 0; sample() returns a).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/solid_angle.hpp>  // triangle_solid_angle
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>

LTC_NAMESPACE_BEGIN

namespace detail {

/// Arc length between unit vectors, 2 asin(|x - y| / 2) (pi minus that of -y past a right angle):
/// accurate at every angle, unlike acos(x.y).
template <typename T>
LTC_HOST_DEVICE inline T arc_length(const glm::vec<3, T>& x, const glm::vec<3, T>& y) {
    const bool obtuse = glm::dot(x, y) < T(0);
    const T half_chord = glm::length(obtuse ? x + y : x - y) / T(2);
    const T half = std::asin(glm::min(T(1), half_chord));
    return obtuse ? pi<T>() - T(2) * half : T(2) * half;
}

/// How far outside its triangle's (or polygon's) edges a sample may land, as the sine of the
/// angle (u = epsilon / 2): sample() puts it within 35 u of the triangle of its unit vertices (c'
/// leaves the arc a c by e's error, 8 u, and the sum's 3 u; the tangent at b 8 u; cos and sin of
/// the arc from b 9 u; the last sum 3 u, normalize 4 u); an edge's normal from stable_cross is
/// off by 5 u in direction (6 u once normalized), and w.n rounds by 3 u: 44 u <= 48 u = 24
/// epsilon.
template <typename T>
LTC_HOST_DEVICE constexpr T sample_margin() {
    return T(24) * epsilon<T>();
}

/// The pdfs' inside test for the edge a b (unit vertices) with inward normal n (any length): w on
/// the inner side of its great circle, or outside by at most sample_margin() (w.n >= -margin |n|,
/// compared squared: |n|, about the chord |b - a|, is far above T's underflow for any edge that T
/// resolves) and on the side of the arc a b (w.(a + b) > 0; an arc of a polygon in an open
/// hemisphere is shorter than pi). The second condition keeps out the antipodes of a polygon
/// narrower than the margin, which are within the margin of every great circle; a sample outside
/// an edge is next to that edge's arc (but where a vertex is collinear with its neighbours to
/// within the margin and the polygon reaches a quarter circle past it along that great circle).
template <typename T>
LTC_HOST_DEVICE inline bool inside_edge(const glm::vec<3, T>& w, const glm::vec<3, T>& n, const glm::vec<3, T>& a,
                                        const glm::vec<3, T>& b) {
    const T d = glm::dot(w, n), m = sample_margin<T>();
    return d >= T(0) || (d * d <= m * m * glm::dot(n, n) && glm::dot(w, a + b) > T(0));
}

/// Unit vector orthogonal to unit x, in the plane of x and y, towards y: (x x y) x x normalized
/// with the cross product of stable_cross (0 when y is +-x).
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> tangent_towards(const glm::vec<3, T>& x, const glm::vec<3, T>& y) {
    return safe_normalize(glm::cross(stable_cross(x, y, glm::dot(x, y)), x));
}

}  // namespace detail

/// Uniform sampling of the spherical triangle (a, b, c) of unit vectors, with all that does not
/// depend on the sample computed once. The triangle must lie in an open hemisphere (as the
/// projection of any planar triangle that misses the origin does).
///
/// The mapping is Arvo's (J. Arvo, "Stratified sampling of spherical triangles", SIGGRAPH 1995) in
/// pbrt-v4's arrangement (SampleSphericalTriangle, InvertSphericalTriangleSample): u.x sets the
/// solid angle A' = u.x A of the sub-triangle (a, b, c'), c' on the arc from a to c, and u.y the
/// point w on the arc from b to c' by 1 - cos|b w| = u.y (1 - cos|b c'|).
///
/// c' is found in closed form from Van Oosterom and Strackee (1983) rather than by Arvo's cos b'
/// formula (docs/design_notes.md). With c' = cos(t) a + sin(t) e, e the unit tangent at a towards c,
/// tan(A'/2) = a.(b x c') / (1 + a.b + a.c' + b.c') is linear-fractional in tau = tan(t/2):
///     tan(A'/2) = tau P / ((1 + a.b) + tau q),    P = e.(a x b),  q = e.b,              (1)
/// whose inverse is
///     tan(t/2) = sin(A'/2) (1 + a.b) / (cos(A'/2) P - sin(A'/2) q).                      (2)
/// Every factor keeps its relative accuracy for tiny, huge and thin triangles: a x b by
/// detail::stable_cross, 1 + a.b = |a + b|^2 / 2, arc lengths by 2 asin(|x - y| / 2), and on the arc
/// sin(|b w| / 2) = sqrt(u.y) |c' - b| / 2. invert() meets the great circle through b and w with the
/// arc a c for c', evaluates (1) for u.x and takes u.y = |w - b|^2 / |c' - b|^2.
template <typename T>
class spherical_triangle_sampler {
  public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    /// An empty sampler (solid angle 0).
    LTC_HOST_DEVICE spherical_triangle_sampler() : a_(T(0)), b_(T(0)) {}

    /// a, b, c: unit vectors, either orientation.
    LTC_HOST_DEVICE spherical_triangle_sampler(const vec3& a, const vec3& b, const vec3& c) : a_(a), b_(b) {
        const T omega = triangle_solid_angle(a, b, c);
        // Coincident or collinear vertices (a flat triangle), or non-finite input.
        if (!(std::abs(omega) > T(0)) || !std::isfinite(omega)) return;
        const T s = omega > T(0) ? T(1) : T(-1);  // orientation: P, the normals and (1) use |.|
        area_ = std::abs(omega);
        e_ = detail::tangent_towards(a, c);
        t_max_ = detail::arc_length(a, c);
        const T half = t_max_ / T(2);
        mid_ = std::cos(half) * a + std::sin(half) * e_;
        n_ab_ = s * detail::stable_cross(a, b, glm::dot(a, b));
        one_plus_ab_ = glm::dot(a + b, a + b) / T(2);
        p_ = glm::max(T(0), glm::dot(e_, n_ab_));  // > 0 but for rounding in flat triangles
        q_ = glm::dot(e_, b);
        n_bc_ = s * detail::stable_cross(b, c, glm::dot(b, c));
        n_ca_ = s * detail::stable_cross(c, a, glm::dot(c, a));
    }

    /// Solid angle |Omega| (Van Oosterom and Strackee); 0 when empty().
    LTC_HOST_DEVICE T solid_angle() const { return area_; }
    /// True for a flat triangle (coincident or collinear vertices) or non-finite input.
    LTC_HOST_DEVICE bool empty() const { return !(area_ > T(0)); }

    /// A direction uniformly distributed in the triangle for u in [0, 1]^2 (the class comment).
    /// Returns a when empty().
    LTC_HOST_DEVICE vec3 sample(const vec2& u) const {
        if (empty()) return a_;
        const vec3 cp = arc_point(arc_parameter(u.x * area_));
        // sin(theta / 2) = sqrt(u.y) sin(theta' / 2), theta' = |b c'|, as 1 - cos = 2 sin^2(/2).
        const vec3 d = cp - b_;
        const T h = glm::min(T(1), std::sqrt(u.y * glm::dot(d, d)) / T(2));
        const T cos_theta = T(1) - T(2) * h * h;
        const T sin_theta = T(2) * h * detail::safe_sqrt(T(1) - h * h);
        return detail::safe_normalize(cos_theta * b_ + sin_theta * detail::tangent_towards(b_, cp));
    }

    /// 1 / solid_angle() for unit w on the inner side of the three great circles, 0 elsewhere (and
    /// when empty()). Every sample has pdf > 0: w also counts as inside an edge when outside its
    /// great circle by at most detail::sample_margin<T>() next to its arc (detail::inside_edge).
    LTC_HOST_DEVICE T pdf(const vec3& w) const {
        if (empty()) return T(0);
        const bool inside = glm::dot(w, n_ab_) >= T(0) && glm::dot(w, n_bc_) >= T(0) && glm::dot(w, n_ca_) >= T(0);
        return inside ? T(1) / area_ : pdf_near_boundary(w);
    }

    /// The u in [0, 1]^2 that sample() maps to the unit direction w, clamped to [0, 1]^2 (u = 0
    /// when empty(); for w outside, the u of a nearby point of the triangle's boundary).
    LTC_HOST_DEVICE vec2 invert(const vec3& w) const {
        if (empty()) return vec2(T(0));
        // c': where the great circle through b and w meets the one through a and c (normal a x e).
        const vec3 n_ac = glm::cross(a_, e_);
        vec3 cp_dir = glm::cross(n_ac, detail::stable_cross(b_, w, glm::dot(b_, w)));
        // The arc a c lies within t_max / 2 < pi / 2 of its midpoint; its antipode does not.
        if (glm::dot(cp_dir, mid_) < T(0)) cp_dir = -cp_dir;
        // w = b (no great circle) gives t = atan2(0, 0) = 0: u = (0, 0).
        const T t = glm::clamp(std::atan2(glm::dot(cp_dir, e_), glm::dot(cp_dir, a_)), T(0), t_max_);
        // (1), as sin and cos of A'/2 up to the same positive factor (A' may exceed pi).
        const T st = std::sin(t / T(2)), ct = std::cos(t / T(2));
        const T sub = T(2) * std::atan2(st * p_, ct * one_plus_ab_ + st * q_);
        const vec3 d = arc_point(t) - b_, e = w - b_;
        const T dd = glm::dot(d, d);
        const T uy = dd > T(0) ? glm::dot(e, e) / dd : T(0);
        return vec2(glm::clamp(sub / area_, T(0), T(1)), glm::clamp(uy, T(0), T(1)));
    }

  private:
    /// pdf() for w outside a great circle: the test with the margin, out of pdf()'s line (c, not
    /// stored, is the end of the arc from a; its rounding does not matter to the sign of w.(b + c)
    /// next to the arc b c).
    LTC_HOST_DEVICE LTC_NOINLINE T pdf_near_boundary(const vec3& w) const {
        const vec3 c = arc_point(t_max_);
        const bool inside = detail::inside_edge(w, n_ab_, a_, b_) && detail::inside_edge(w, n_bc_, b_, c) &&
                            detail::inside_edge(w, n_ca_, c, a_);
        return inside ? T(1) / area_ : T(0);
    }

    /// The arc length t of c' from a for the sub-triangle's solid angle sub in [0, area_]: (2),
    /// with sin and cos of A'/2 (A' may exceed pi, and then cos(A'/2) < 0).
    LTC_HOST_DEVICE T arc_parameter(T sub) const {
        const T s = std::sin(sub / T(2)), c = std::cos(sub / T(2));
        return glm::clamp(T(2) * std::atan2(s * one_plus_ab_, c * p_ - s * q_), T(0), t_max_);
    }
    LTC_HOST_DEVICE vec3 arc_point(T t) const { return std::cos(t) * a_ + std::sin(t) * e_; }

    vec3 a_, b_;
    vec3 e_{T(0)}, mid_{T(0)};                      // tangent at a towards c; midpoint of the arc a c
    vec3 n_ab_{T(0)}, n_bc_{T(0)}, n_ca_{T(0)};     // inward normals of the edges' great circles
    T area_ = T(0), t_max_ = T(0);                  // solid angle; arc length |a c|
    T one_plus_ab_ = T(0), p_ = T(0), q_ = T(0);    // the constants of (1) and (2)
};

LTC_NAMESPACE_END
