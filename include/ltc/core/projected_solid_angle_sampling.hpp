// ltc/core/projected_solid_angle_sampling.hpp -- exact sampling of the clamped cosine restricted
// to a spherical polygon: directions with density w.z / E over the part of the polygon above the
// horizon, E = int_P max(0, w.z) dw = pi times the form factor of the paper's eq. (11). This is
// what Peters ("BRDF Importance Sampling for Polygonal Lights", SIGGRAPH 2021) calls projected
// solid angle sampling; the method (projected_polygon_sampler) is derived in this library, and any
// LTC restricted to a polygon is sampled through it (ltc/core/ltc_polygon_sampling.hpp).
//
//   ltc::projected_polygon_sampler<float> s(vertices, n);   // shading frame, z = normal
//   ltc::polygon_sample<float> x = s.sample(u);               // x.pdf = x.direction.z / E
//   glm::vec2 v = s.invert(x.direction);                      // == u up to rounding
//
// Conventions: a convex planar polygon, any scale, either winding, at most max_vertices (8 by
// default) vertices (checked() throws ltc::invalid_polygon). Degenerate cases: n < 3, a vertex at
// the origin or a polygon below the horizon give an empty() sampler (pdf 0 everywhere).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/horizon_clip.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/detail/polygon_check.hpp>
#include <ltc/core/detail/projected_triangle.hpp>
#include <ltc/detail/wider.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <type_traits>

LTC_NAMESPACE_BEGIN

/// A sampled direction and its density (per steradian).
template <typename T>
struct polygon_sample {
    glm::vec<3, T> direction{T(0), T(0), T(1)};
    T pdf{0};
};

namespace detail {

/// The fan of triangles (v0, v_i, v_i+1) of a clipped polygon, in precision C: their masses'
/// cumulative sums choose the triangle, and u.x is rescaled into it.
template <typename C, std::size_t N>
struct projected_fan {
    projected_triangle<C> tris[N]{};
    C cdf[N]{};
    std::size_t count = 0;
    C total{0}, worst_condition{0};
    C orientation{1};  // the sign of the largest triangle: the polygon's orientation

    /// The unit vertices v (in T) as unit vectors in C: renormalized when C is wider.
    template <typename T>
    LTC_HOST_DEVICE static glm::vec<3, C> unit(const glm::vec<3, T>& v) {
        if constexpr (std::is_same_v<T, C>) return v;
        else return safe_normalize(glm::vec<3, C>(v));
    }

    template <typename T>
    LTC_HOST_DEVICE void build(const glm::vec<3, T>* v, std::size_t m) {
        count = 0;
        total = worst_condition = C(0);
        C largest(0);
        for (std::size_t i = 1; i + 1 < m; ++i) {
            projected_triangle<C>& t = tris[count++];
            t = projected_triangle<C>(unit(v[0]), unit(v[i]), unit(v[i + 1]));
            total += t.mass;
            cdf[count - 1] = total;
            worst_condition = glm::max(worst_condition, t.condition);
            if (t.mass > largest) largest = t.mass, orientation = t.sign;
        }
    }

    /// Samples triangle k (returned) with u.x rescaled into it.
    LTC_HOST_DEVICE glm::vec<3, C> sample(C ux, C uy, std::size_t& k, int& evaluations) const {
        k = 0;
        const C target = ux * total;
        while (k + 1 < count && (cdf[k] <= target || !(tris[k].mass > C(0)))) ++k;
        while (k > 0 && !(tris[k].mass > C(0))) --k;  // u.x = 1 with a flat last triangle
        const projected_triangle<C>& t = tris[k];
        const C below = k > 0 ? cdf[k - 1] : C(0);
        const C u1 = t.mass > C(0) ? glm::clamp((target - below) / t.mass, C(0), C(1)) : C(0);
        return t.sample(u1, uy, evaluations);
    }

    LTC_HOST_DEVICE glm::vec<2, C> invert(const glm::vec<3, C>& w) const {
        // The fan triangle whose angle at the apex holds w.
        std::size_t k = 0;
        for (; k + 1 < count; ++k) {
            const projected_triangle<C>& t = tris[k];
            const glm::vec<3, C> wa = w - t.a;
            if (std::atan2(glm::dot(wa, t.t_c), glm::dot(wa, t.t_b)) <= t.alpha) break;
        }
        const glm::vec<2, C> local = tris[k].invert(w);
        const C below = k > 0 ? cdf[k - 1] : C(0);
        return glm::vec<2, C>(glm::clamp((below + local.x * tris[k].mass) / total, C(0), C(1)), local.y);
    }
};

/// Stands in for the wide fan when Wide is T itself (never used).
struct no_fan {};

}  // namespace detail

/// Sampling of w.z over a convex spherical polygon clipped to the horizon.
///
/// Method. The polygon is clipped to z >= 0 (Sutherland-Hodgman, as eq. 11 requires) and cut
/// into a fan of triangles from its first vertex; u.x picks a triangle with probability
/// proportional to its projected solid angle (Lambert's formula, the edge terms of eq. 11) and is
/// rescaled to [0, 1) inside it. In the triangle (ltc/core/detail/projected_triangle.hpp), u.x fixes
/// the great circle through the apex that cuts off the fraction u.x of its projected solid angle
/// (closed form, one Newton solve in the angle at the apex: its derivative is a closed form too),
/// and u.y the point along that arc (the arc's cosine-weighted length, a second Newton solve).
/// Both solves run inside bisection brackets to about 4 epsilon of the target, so the
/// distribution is exact to rounding and invert() (closed forms, no solve) is its inverse.
///
/// Accuracy. A fan triangle's projected solid angle is a sum of edge terms that cancel: for a
/// triangle of angular size h it is ~h^2 from terms of size h, for a sliver of height d above the
/// horizon ~d^2 from terms of its width, and F's relative error is epsilon times their ratio
/// (projected_triangle::condition). Where that exceeds 2^-12 in some fan triangle (in float: a
/// triangle under ~1e-3 rad, or a sliver within ~0.01 rad of the horizon), the whole fan is
/// rebuilt in the wider type Wide (double for float; Wide = T opts out, e.g. on a GPU) from the
/// input vertices: converted exactly, then clipped and normalized in Wide (and, for
/// ltc_polygon_sampler, multiplied by M^-1 in Wide), since T's unit vertices alone are off by
/// epsilon, which is epsilon / h of the size h of a tiny polygon. The distribution then stays
/// w.z / E to ~2^-12 or better in float (E itself is the rounding to T of its value in Wide, for
/// polygons of the size Wide resolves) and to rounding in double; pdf()'s great circles are
/// those of the unit vertices in Wide, rounded to T.
///
/// Preconditions and degenerate input. A convex planar polygon (light polygons are), any scale,
/// either winding, at most max_vertices (MaxVertices, 8 by default) vertices: checked() throws
/// ltc::invalid_polygon above it. n < 3, n > max_vertices, a vertex at the origin or a polygon
/// wholly below the horizon (or within rounding of it) give an empty() sampler:
/// projected_solid_angle() 0, pdf() 0, and sample() the normal (0, 0, 1) with pdf 0; every sample
/// of a sampler that is not empty() has pdf() > 0, the pdf it carries.
template <typename T, std::size_t MaxVertices = 8, typename Wide = detail::wider_t<T>>
class projected_polygon_sampler {
  public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;
    /// The capacity: the most vertices a polygon may have, the MaxVertices template argument (a
    /// larger one holds larger polygons). n <= max_vertices is a precondition of the constructor,
    /// which gives an empty() sampler above it (it cannot throw: device code); checked() throws.
    static constexpr std::size_t max_vertices = MaxVertices;
    static constexpr std::size_t capacity = clipped_capacity(MaxVertices);  // of the clipped polygon

    LTC_HOST_DEVICE projected_polygon_sampler() = default;

    /// vertices[0..n): the polygon seen from the origin, in the frame whose z is the normal.
    LTC_HOST_DEVICE projected_polygon_sampler(const vec3* vertices, std::size_t n) {
        init(vertices, n, nullptr, nullptr);
    }

    /// The polygon m_inv raw[0..n) (ltc_polygon_sampler's M^-1 P), given also as vertices[i], the
    /// product evaluated in T (up to a positive factor each): the fan in T is built from vertices,
    /// a fan in Wide recomputes the product in Wide (the class comment's Accuracy).
    LTC_HOST_DEVICE projected_polygon_sampler(const vec3* vertices, std::size_t n, const glm::mat<3, 3, T>& m_inv,
                                              const vec3* raw) {
        init(vertices, n, &m_inv, raw);
    }

    /// Like the first constructor, but throws ltc::invalid_polygon (ltc/core/invalid_polygon.hpp)
    /// for n > max_vertices, n < 3 or a vertex not finite: input that is no polygon it can hold.
    /// (A polygon below the horizon or seen edge-on still gives an empty() sampler.)
    static projected_polygon_sampler checked(const vec3* vertices, std::size_t n) {
        detail::require_polygon("ltc::projected_polygon_sampler", vertices, n, max_vertices);
        return projected_polygon_sampler(vertices, n);
    }

    LTC_HOST_DEVICE bool empty() const { return !(total_ > T(0)); }

    /// E = int_P max(0, w.z) dw (pi times eq. 11's clipped form factor).
    LTC_HOST_DEVICE T projected_solid_angle() const { return total_; }

    /// Whether the fan is evaluated in Wide (the class comment's Accuracy).
    LTC_HOST_DEVICE bool widened() const { return wide_; }

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
        const vec2 c = glm::clamp(u, T(0), T(1));
        std::size_t k = 0;
        vec3 w;
        if constexpr (widens) {
            if (wide_) w = vec3(wide_fan_.sample(Wide(c.x), Wide(c.y), k, evaluations));
            else w = fan_.sample(c.x, c.y, k, evaluations);
        } else {
            w = fan_.sample(c.x, c.y, k, evaluations);
        }
        w = detail::safe_normalize(w);
        // A sample on the horizon (u on the border of the square with a vertex at z = 0) has
        // density 0: move it into the triangle by the smallest power-of-16 multiple of epsilon
        // that makes it positive (a bias confined to a set of measure ~epsilon).
        if (!(w.z / total_ > T(0))) {  // also a w.z so small that w.z / E underflows
            vec3 centre = detail::safe_normalize(v_[0] + v_[k + 1] + v_[k + 2]);
            if (!(centre.z > T(0))) centre = interior();  // a triangle flat on the horizon
            T lift = detail::epsilon<T>();
            for (int i = 0; i < 16 && !(w.z / total_ > T(0)); ++i, lift *= T(16))
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
        if constexpr (widens) {
            if (wide_) return vec2(wide_fan_.invert(glm::vec<3, Wide>(w)));
        }
        return fan_.invert(w);
    }

    /// A direction inside the polygon (the normalized sum of its vertices; convex polygon).
    LTC_HOST_DEVICE vec3 interior() const {
        vec3 c(T(0));
        for (std::size_t i = 0; i < vertex_count_; ++i) c += v_[i];
        return detail::safe_normalize(c);
    }

    /// The clipped polygon's unit vertices (for tests and visualisation).
    LTC_HOST_DEVICE std::size_t vertex_count() const { return vertex_count_; }
    LTC_HOST_DEVICE const vec3& vertex(std::size_t i) const { return v_[i]; }

  private:
    static constexpr bool widens = !std::is_same_v<T, Wide>;
    using wide_vec3 = glm::vec<3, Wide>;

    /// The constructors: m_inv null for the polygon vertices[0..n) itself.
    LTC_HOST_DEVICE void init(const vec3* vertices, std::size_t n, const glm::mat<3, 3, T>* m_inv,
                              const vec3* raw) {
        if (n < 3 || n > MaxVertices) return;
        vec3 clipped[capacity];
        std::size_t m = clip_to_horizon(vertices, n, clipped);
        if (m < 3) return;
        for (std::size_t i = 0; i < m; ++i) {
            v_[i] = detail::safe_normalize(clipped[i]);
            if (v_[i] == vec3(T(0)) || !detail::is_finite(v_[i])) return;  // seen edge-on
        }
        fan_.build(v_, m);
        T total = fan_.total, orientation = fan_.orientation;
        bool normals_done = false;
        if constexpr (widens) {
            if (fan_.worst_condition * detail::epsilon<T>() > T(1.0 / 4096)) {
                // The input once more in Wide: converted exactly (and multiplied by M^-1 in Wide),
                // clipped and normalized in Wide, so that the fan sees no rounding of T.
                wide_vec3 in[MaxVertices], wclipped[capacity], wv[capacity];
                for (std::size_t i = 0; i < n; ++i)
                    in[i] = m_inv ? glm::mat<3, 3, Wide>(*m_inv) * wide_vec3(raw[i]) : wide_vec3(vertices[i]);
                const std::size_t mw = clip_to_horizon(in, n, wclipped);
                bool ok = mw >= 3;
                for (std::size_t i = 0; ok && i < mw; ++i) {
                    wv[i] = detail::safe_normalize(wclipped[i]);
                    ok = wv[i] != wide_vec3(Wide(0)) && detail::is_finite(wv[i]);
                }
                if (ok) {
                    wide_fan_.build(wv, mw);
                    wide_ = true;
                    total = T(wide_fan_.total);
                    orientation = T(wide_fan_.orientation);
                    // The unit vertices and the inward great-circle normals for pdf() from Wide.
                    m = mw;
                    for (std::size_t i = 0; i < m; ++i) {
                        const wide_vec3& p = wv[i];
                        const wide_vec3& q = wv[(i + 1) % m];
                        v_[i] = vec3(p);
                        edge_normal_[i] = vec3(Wide(orientation) * detail::stable_cross(p, q, glm::dot(p, q)));
                    }
                    normals_done = true;
                }
            }
        }
        // pdf = w.z / E <= 1 / E must stay finite: a subnormal E is an empty polygon.
        if (!(total >= T(4) * detail::min_normal<T>()) || !std::isfinite(total)) return;
        vertex_count_ = m;
        total_ = total;
        // Great-circle normals pointing inwards, for pdf().
        for (std::size_t i = 0; !normals_done && i < m; ++i) {
            const vec3& p = v_[i];
            const vec3& q = v_[(i + 1) % m];
            edge_normal_[i] = orientation * detail::stable_cross(p, q, glm::dot(p, q));
        }
    }

    vec3 v_[capacity]{};
    vec3 edge_normal_[capacity]{};
    detail::projected_fan<T, capacity - 2> fan_;
    std::conditional_t<widens, detail::projected_fan<Wide, capacity - 2>, detail::no_fan> wide_fan_;
    std::size_t vertex_count_ = 0;
    T total_{0};
    bool wide_ = false;
};

LTC_NAMESPACE_END
