// ltc/shading/lights/tube_light.hpp -- a constant-radiance tube light, with the tube's silhouette
// exact: the cylinder replaced by the planar quad (the "ribbon") that covers the same directions,
// integrated exactly by the polygon integral (paper eq. 11 for the form factor, eq. 3 and 11
// through M^-1 for the LTC). Where ltc/shading/lights/line_light.hpp (the 2017 thin line,
// 2 r I_line) fails for close or wide tubes (2 r I_line > 1), this stays bounded.
//
//   ltc::tube_light<float> tube{p0, p1, radius, radiance};
//   ltc::shading_result<float> r = ltc::shade(surface, tube);   // ltc/shading/shade.hpp
//
//   diffuse  = albedo * radiance * E(ribbon)                                   (eq. 11, |signed|)
//   specular = radiance * (F0 magnitude + (1 - F0) fresnel) * I_ltc(ribbon)   (eq. 3 + 11, |signed|)
//
// Conventions: world space; an open cylinder (no end caps), glowing all around: two-sided; the
// ribbon horizon-clipped as shade_options::clip says. Degenerate cases: radius <= 0 (or NaN),
// p0 = p1 or non-finite input give 0; P within the radius sees the wall (tube_light).
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/ellipse_integral.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/polygon_light_integrals.hpp>
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/surface.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

LTC_NAMESPACE_BEGIN

/// What a tube (axis p0-p1, radius) is from P (make_tube_ribbon): `ribbon`, the quad corner[0..4)
/// covering the same directions (but for the ends); `inside` (P within `radius` of the axis);
/// `nothing` (radius <= 0, p0 = p1, non-finite input). Coordinates are world space times
/// `scale`, a power of two (1 unless the input is within a factor 16 of overflow): `origin` = P scale,
/// `start`, `end` = p0, p1 scale, `axis` = t, `along` = (P - p0).t scale, `length` = |p1 - p0|
/// scale, `radius` = radius scale.
template <typename T>
struct tube_ribbon {
    enum kind_t { nothing, ribbon, inside } kind = nothing;
    glm::vec<3, T> corner[4] = {glm::vec<3, T>(T(0)), glm::vec<3, T>(T(0)), glm::vec<3, T>(T(0)),
                                glm::vec<3, T>(T(0))};
    glm::vec<3, T> origin{T(0)}, start{T(0)}, end{T(0)}, axis{T(0), T(0), T(1)};
    T scale{1}, along{0}, length{0}, radius{0};
};

namespace detail {
/// |v| without overflow or underflow of the squares (scaled by the largest coordinate).
template <typename T>
inline T tube_length(const glm::vec<3, T>& v) {
    const T big = std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
    return big > T(0) ? big * glm::length(v / big) : T(0);
}
}  // namespace detail

/// The ribbon of the tube p0-p1 of the given radius seen from P. Derivation: let the axis run
/// through p0 with unit direction t, and P lie at distance rho > r from it, u the unit vector from
/// the axis towards P. A ray from P hits the infinite cylinder iff its projection along t (onto
/// the cross-section plane) hits the circle of radius r: the rays within the wedge of half-angle
/// asin(r/rho) around -u, bounded by the two tangent lines from P's projection. The chord through
/// the two tangent points spans the same wedge; in 3D it is the strip parallel to the axis
///   centre line  axis + u r^2/rho,   half-width  w = r sqrt(1 - r^2/rho^2)   (along t x u),
/// computed as r sqrt((rho - r)/rho * (rho + r)/rho) (no cancellation close to the tube, no
/// overflow of rho^2). So the infinite strip and the infinite cylinder cover exactly the same
/// directions (as the sphere and its disk of tangency, ltc/shading/lights/sphere_light.hpp). The
/// finite tube p0-p1 becomes the strip cut by the planes through p0 and p1 perpendicular to t:
/// the quad
///   p0 + u r^2/rho +- w (t x u),   p1 + u r^2/rho -+ w (t x u).
/// Huge coordinates: everything is scaled by a power of two (exact; only directions matter) when
/// a coordinate or the radius exceeds 1/16 of the largest finite value.
template <typename T>
inline tube_ribbon<T> make_tube_ribbon(const glm::vec<3, T>& P, const glm::vec<3, T>& p0, const glm::vec<3, T>& p1,
                                       T radius) {
    using vec3 = glm::vec<3, T>;
    tube_ribbon<T> q;
    const auto top = [](const vec3& v) { return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))); };
    const T m = std::max(std::max(top(P), top(p0)), std::max(top(p1), radius));
    if (!(radius > T(0)) || !(m <= std::numeric_limits<T>::max())) return q;  // also catches NaN
    const T s = m > std::numeric_limits<T>::max() / T(16) ? std::ldexp(T(1), -std::ilogb(m)) : T(1);
    const vec3 o = P * s, a = p0 * s, b = p1 * s;
    const T r = radius * s;
    const vec3 e = b - a;
    const T len = detail::tube_length(e);
    if (!(len > T(0))) return q;  // p0 = p1
    const vec3 t = e / len, d = o - a;
    const T along = glm::dot(d, t);
    const vec3 perp = d - along * t;  // from the axis to P
    const T rho = detail::tube_length(perp);
    q.scale = s;
    q.origin = o;
    q.start = a;
    q.end = b;
    q.axis = t;
    q.along = along;
    q.length = len;
    q.radius = r;
    if (!(rho > r)) {
        q.kind = tube_ribbon<T>::inside;
        return q;
    }
    const vec3 u = perp / rho, across = glm::cross(t, u);
    const T offset = r * (r / rho);                                       // r^2 / rho
    const T half = r * std::sqrt((rho - r) / rho * ((rho + r) / rho));   // r sqrt(1 - r^2/rho^2)
    const vec3 shift = u * offset, side = across * half;
    q.corner[0] = a + shift + side;
    q.corner[1] = b + shift + side;
    q.corner[2] = b + shift - side;
    q.corner[3] = a + shift - side;
    q.kind = tube_ribbon<T>::ribbon;
    return q;
}

/// A constant-radiance open tube light. World space: the tube's axis p0-p1, its radius and
/// radiance; an aggregate. An open cylinder (no end caps, as ground_truth::integrate_tube); it
/// glows all around: two-sided. Outside the tube, its ribbon (make_tube_ribbon) is integrated.
///
/// What is exact and what is not. Exact (to rounding; the polygon integral is): the silhouette
/// across the axis, everywhere along it, for any distance rho > r (no thin-tube assumption). Not
/// exact: the ends. A ray's projection crosses the chord between its entry and exit points on the
/// circle, so the ribbon's hit point along the axis lies between the cylinder's two; near the
/// planes of p0 and p1 the ray can hit the cylinder and miss the ribbon or the converse: a sliver
/// of directions O(r / length) of the tube's, near each end (the "ribbon" columns of
/// tools/shape_error_report, docs/results/shape_error.md: the GGX over the quad by Monte Carlo
/// against the real cylinder's).
///
/// P within r of the axis (rho <= r; tube_ribbon's `inside`): within the span (0 <= along <= L)
/// the tube surrounds P: every direction but those through the two open ends,
///   I = 1 - |I_disk(p0)| - |I_disk(p1)|,
/// the disks of radius r with normal t at p0 and p1 (integrate_disk, exact, horizon-clipped; D and
/// the clamped cosine integrate to 1 over the upper hemisphere); beyond an end (along < 0 or > L),
/// inside the infinite cylinder, P sees the inner wall through the near opening and not through
/// the far one: I = |I_disk(near)| - |I_disk(far)| (the far disk's cone lies within the near
/// one's). Exact for the open tube.
///
/// Degenerate input gives finite results: radius <= 0 (or NaN), p0 = p1, non-finite input
/// give 0.
template <typename T>
struct tube_light {
    using vec3 = glm::vec<3, T>;
    vec3 p0{T(0)}, p1{T(0)};
    T radius{0};
    vec3 radiance{T(0)};

    // The light interface of ltc::shade (ltc/shading/lights/polygon_light.hpp).
    template <typename Policy>
    polygon_light_integrals<T> integrals(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                                         const shade_options& o) const {
        polygon_light_integrals<T> I;
        const tube_ribbon<T> q = make_tube_ribbon(P, p0, p1, radius);
        if (!frame.valid || q.kind == tube_ribbon<T>::nothing) return I;
        if (q.kind == tube_ribbon<T>::ribbon) {
            I = integrate_polygon_light<Policy>(frame, m_inv, q.origin, q.corner, 4, o.clip);
            I.form_factor = apply_sidedness(I.form_factor, sidedness::two_sided);
            I.ltc = apply_sidedness(I.ltc, sidedness::two_sided);
            return I;
        }
        I.ltc = wall(frame, q, m_inv);
        I.form_factor = wall(frame, q, glm::mat<3, 3, T>(T(1)));
        return I;
    }
    template <typename Policy>
    T ltc_integral(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                   const shade_options& o) const {
        const tube_ribbon<T> q = make_tube_ribbon(P, p0, p1, radius);
        if (!frame.valid || q.kind == tube_ribbon<T>::nothing) return T(0);
        if (q.kind == tube_ribbon<T>::ribbon)
            return apply_sidedness(integrate_polygon_light_ltc<Policy>(frame, m_inv, q.origin, q.corner, 4, o.clip),
                                   sidedness::two_sided);
        return wall(frame, q, m_inv);
    }
    vec3 emitted(const vec3& scale, T integral) const { return radiance * scale * integral; }

private:
    // Inside the infinite cylinder: the wall seen between the openings (the struct's comment).
    static T wall(const shading_frame<T>& frame, const tube_ribbon<T>& q, const glm::mat<3, 3, T>& m_inv) {
        const auto d = transformed<clamped_cosine<T>>::from_inverse(m_inv);
        const vec3 c0 = frame.to_local(q.start - q.origin), n = frame.to_local(q.axis);
        const vec3 c1 = frame.to_local(q.end - q.origin);
        const T i0 = integrate_disk(d, c0, n, q.radius, sidedness::two_sided);
        const T i1 = integrate_disk(d, c1, n, q.radius, sidedness::two_sided);
        const T w = q.along < T(0) ? i0 - i1 : q.along > q.length ? i1 - i0 : T(1) - i0 - i1;
        return std::min(T(1), std::max(T(0), w));
    }
};

LTC_NAMESPACE_END
