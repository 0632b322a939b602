// ltc/core/projected_solid_angle_sampling.hpp -- exact sampling of the clamped cosine restricted
// to a spherical polygon: directions with density w.z / E over the part of the polygon above the
// horizon, E = int_P max(0, w.z) dw = pi times the form factor of the paper's eq. (11). This is
// what Peters ("BRDF Importance Sampling for Polygonal Lights", SIGGRAPH 2021) calls projected
// solid angle sampling; the method here is derived in this library (not Peters' ellipse
// construction), and any LTC restricted to a polygon is sampled through it
// (ltc/core/ltc_polygon_sampling.hpp).
//
//   ltc::projected_polygon_sampler<float> s(vertices, n);   // shading frame, z = normal
//   ltc::polygon_sample<float> x = s.sample(u);               // x.pdf = x.direction.z / E
//   glm::vec2 v = s.invert(x.direction);                      // == u up to rounding
//
// Method. The polygon is clipped to z >= 0 (Sutherland-Hodgman, as eq. 11 requires) and cut
// into a fan of triangles from its first vertex; u.x picks a triangle with probability
// proportional to its projected solid angle (Lambert's formula, the edge terms of eq. 11) and is
// rescaled to [0, 1) inside it. In the triangle (ltc/detail/projected_triangle.hpp), u.x fixes
// the great circle through the apex that cuts off the fraction u.x of its projected solid angle
// (closed form, one Newton solve in the angle at the apex: its derivative is a closed form too),
// and u.y the point along that arc (the arc's cosine-weighted length, a second Newton solve).
// Both solves run inside bisection brackets to about 4 epsilon of the target, so the
// distribution is exact to rounding and invert() (closed forms, no solve) is its inverse.
//
// Accuracy. The projected solid angle of a triangle of angular size h is a sum of edge terms of
// size h that cancel to h^2: relative error ~ epsilon / h, i.e. 1e-4 for a float triangle of a
// thousandth of a radian (in double, 1e-13). The sampled directions are inside the polygon for
// any size; what degrades for tiny triangles is the match of the density to w.z, which is then
// nearly constant over the triangle anyway.
//
// Preconditions and degenerate input. A convex planar polygon (light polygons are), any scale,
// either winding, at most MaxVertices vertices. n < 3, n > MaxVertices, a vertex at the origin
// or a polygon wholly below the horizon (or within rounding of it) give an empty() sampler:
// projected_solid_angle() 0, pdf() 0, and sample() the normal (0, 0, 1) with pdf 0.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/horizon_clip.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/detail/projected_triangle.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

namespace ltc {

/// A sampled direction and its density (per steradian).
template <typename T>
struct polygon_sample {
    glm::vec<3, T> direction{T(0), T(0), T(1)};
    T pdf{0};
};

/// Sampling of w.z over a convex spherical polygon clipped to the horizon (file comment).
template <typename T, std::size_t MaxVertices = 8>
class projected_polygon_sampler {
  public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;
    static constexpr std::size_t capacity = clipped_capacity(MaxVertices);

    LTC_HOST_DEVICE projected_polygon_sampler() = default;

    /// vertices[0..n): the polygon seen from the origin, in the frame whose z is the normal.
    LTC_HOST_DEVICE projected_polygon_sampler(const vec3* vertices, std::size_t n) {
        if (n < 3 || n > MaxVertices) return;
        vec3 clipped[capacity];
        const std::size_t m = clip_to_horizon(vertices, n, clipped);
        if (m < 3) return;
        for (std::size_t i = 0; i < m; ++i) {
            v_[i] = detail::safe_normalize(clipped[i]);
            if (v_[i] == vec3(T(0)) || !detail::is_finite(v_[i])) return;  // seen edge-on
        }
        T total(0), largest(0);
        for (std::size_t i = 1; i + 1 < m; ++i) {
            detail::projected_triangle<T>& t = tris_[count_++];
            t = detail::projected_triangle<T>(v_[0], v_[i], v_[i + 1]);
            total += t.mass;
            cdf_[count_ - 1] = total;
            if (t.mass > largest) largest = t.mass, orientation_ = t.sign;
        }
        if (!(total > T(0)) || !std::isfinite(total)) return;
        vertex_count_ = m;
        total_ = total;
        // Great-circle normals pointing inwards, for pdf(): the fan triangle of largest mass gives
        // the orientation (sign) of the whole convex polygon.
        for (std::size_t i = 0; i < m; ++i) {
            const vec3& p = v_[i];
            const vec3& q = v_[(i + 1) % m];
            edge_normal_[i] = orientation_ * detail::stable_cross(p, q, glm::dot(p, q));
        }
    }

    LTC_HOST_DEVICE bool empty() const { return !(total_ > T(0)); }

    /// E = int_P max(0, w.z) dw (pi times eq. 11's clipped form factor).
    LTC_HOST_DEVICE T projected_solid_angle() const { return total_; }

    /// A direction with density direction.z / E in the polygon, for u in [0, 1]^2. The returned
    /// pdf is the density at the sample (computed from it, without a containment test).
    LTC_HOST_DEVICE polygon_sample<T> sample(const vec2& u) const {
        int evaluations = 0;
        return sample(u, evaluations);
    }

    /// The same, adding to `evaluations` the number of closed-form evaluations the two solves
    /// took (each evaluation of F or W, with its derivative, counts once).
    LTC_HOST_DEVICE polygon_sample<T> sample(const vec2& u, int& evaluations) const {
        polygon_sample<T> r;
        if (empty()) return r;
        std::size_t k = 0;
        const T target = glm::clamp(u.x, T(0), T(1)) * total_;
        while (k + 1 < count_ && (cdf_[k] <= target || !(tris_[k].mass > T(0)))) ++k;
        const detail::projected_triangle<T>& t = tris_[k];
        const T below = k > 0 ? cdf_[k - 1] : T(0);
        const T u1 = t.mass > T(0) ? glm::clamp((target - below) / t.mass, T(0), T(1)) : T(0);
        vec3 w = detail::safe_normalize(t.sample(u1, glm::clamp(u.y, T(0), T(1)), evaluations));
        // A sample on the horizon (u on the border of the square with a vertex at z = 0) has
        // density 0: move it into the triangle by the smallest power-of-16 multiple of epsilon
        // that makes it positive (a bias confined to a set of measure ~epsilon).
        if (!(w.z > T(0))) {
            const vec3 centre = detail::safe_normalize(v_[0] + v_[k + 1] + v_[k + 2]);
            T lift = detail::epsilon<T>();
            for (int i = 0; i < 16 && !(w.z > T(0)); ++i, lift *= T(16))
                w = detail::safe_normalize(w + lift * centre);
        }
        r.direction = w;
        r.pdf = glm::max(w.z, T(0)) / total_;
        return r;
    }

    /// Density of sample() at the unit direction w: w.z / E inside the clipped polygon, else 0.
    /// Directions within a few epsilon of an edge's great circle count as inside.
    LTC_HOST_DEVICE T pdf(const vec3& w) const {
        if (empty() || !(w.z > T(0))) return T(0);
        for (std::size_t i = 0; i < vertex_count_; ++i) {
            const T margin = T(8) * detail::epsilon<T>() * glm::length(edge_normal_[i]);
            if (glm::dot(w, edge_normal_[i]) < -margin) return T(0);
        }
        return w.z / total_;
    }

    /// u with sample(u).direction == w (up to the solves' tolerance), for w in the polygon; the
    /// nearest point of the square for w outside.
    LTC_HOST_DEVICE vec2 invert(const vec3& w) const {
        if (empty()) return vec2(T(0));
        // The fan triangle whose angle at the apex holds w.
        std::size_t k = 0;
        for (; k + 1 < count_; ++k) {
            const detail::projected_triangle<T>& t = tris_[k];
            const vec3 wa = w - t.a;
            if (std::atan2(glm::dot(wa, t.t_c), glm::dot(wa, t.t_b)) <= t.alpha) break;
        }
        const vec2 local = tris_[k].invert(w);
        const T below = k > 0 ? cdf_[k - 1] : T(0);
        return vec2(glm::clamp((below + local.x * tris_[k].mass) / total_, T(0), T(1)), local.y);
    }

    /// The clipped polygon's unit vertices (for tests and visualisation).
    LTC_HOST_DEVICE std::size_t vertex_count() const { return vertex_count_; }
    LTC_HOST_DEVICE const vec3& vertex(std::size_t i) const { return v_[i]; }

  private:
    vec3 v_[capacity]{};
    vec3 edge_normal_[capacity]{};
    detail::projected_triangle<T> tris_[capacity - 2]{};
    T cdf_[capacity - 2]{};
    std::size_t count_ = 0, vertex_count_ = 0;
    T total_{0};
    T orientation_{1};
};

}  // namespace ltc
