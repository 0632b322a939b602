// ltc/shading/lights/sphere_light.hpp -- a constant-radiance sphere light, integrated exactly: a
// sphere of radius R whose centre is at distance d > R covers the same directions as the disk
// facing the point through its circle of tangency (the base of the cone it subtends):
//
//   centre' = P + (C - P) (1 - R^2/d^2),  normal' = (P - C)/d,  radius' = R sqrt(1 - R^2/d^2),
//
// so its LTC integral is the disk's (ltc/shading/lights/disk_light.hpp, exact to rounding), not an
// approximation: the method Blender EEVEE and the 2017 course (Heitz and Hill) use for spheres.
//
//   ltc::sphere_light<float> sphere{centre, radius, radiance};
//   ltc::shading_result<float> r = ltc::shade(surface, sphere);   // ltc/shading/shade.hpp
//
// Conventions: world space, an aggregate; the sphere glows all around: no sidedness. Degenerate
// cases: P inside or on the sphere (d <= R) sees the whole LTC, I = 1 and E = 1; radius <= 0 or
// non-finite input gives 0.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/sidedness.hpp>
#include <ltc/shading/lights/disk_light.hpp>
#include <ltc/shading/polygon_light_integrals.hpp>  // polygon_light_integrals
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/surface.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

LTC_NAMESPACE_BEGIN

/// What a sphere (centre, radius) is from P (view_sphere): `disk`, the disk that covers the
/// same directions; `inside` (d <= R: every direction); or `nothing` (radius <= 0 or NaN,
/// non-finite input).
template <typename T>
struct sphere_view {
    enum kind_t { nothing, disk, inside } kind = nothing;
    glm::vec<3, T> centre{T(0)}, normal{T(0), T(0), T(1)};
    T radius{0};
};

/// The sphere seen from P: its disk of tangency, with 1 - R^2/d^2 computed as (d - R)(d + R)/d^2
/// (no cancellation for a point close to the sphere). Uniform radiance, so only the directions
/// matter.
template <typename T>
inline sphere_view<T> view_sphere(const glm::vec<3, T>& P, const glm::vec<3, T>& centre, T radius) {
    sphere_view<T> s;
    const glm::vec<3, T> to_centre = centre - P;
    // Scaled by the largest coordinate first, so that |to_centre| cannot overflow.
    const T big = std::max(std::abs(to_centre.x), std::max(std::abs(to_centre.y), std::abs(to_centre.z)));
    // Each coordinate tested: std::max drops a NaN in its second argument.
    const bool finite = std::isfinite(to_centre.x) && std::isfinite(to_centre.y) && std::isfinite(to_centre.z);
    if (!finite || !(radius > T(0)) || !(radius <= std::numeric_limits<T>::max())) return s;
    const T d = big > T(0) ? big * glm::length(to_centre / big) : T(0);
    if (!(d > radius)) {
        s.kind = sphere_view<T>::inside;
        return s;
    }
    const T keep = (d - radius) / d * ((d + radius) / d);  // 1 - R^2/d^2
    s.kind = sphere_view<T>::disk;
    s.centre = P + to_centre * keep;
    s.normal = -to_centre / d;
    s.radius = radius * std::sqrt(keep);
    return s;
}

/// A constant-radiance sphere light: the disk of view_sphere, integrated exactly (with the exact
/// disk integral). World space; an aggregate (no invariant to check). The sphere glows all
/// around: no sidedness. A shading point inside the sphere or on it (d <= R) sees it in every
/// direction: the whole LTC, I = 1 (D integrates to 1), and E = 1; radius <= 0 or non-finite
/// input gives 0. The shading's error is the GGX fit's (tools/shape_error_report,
/// docs/results/shape_error.md, including spheres straddling the horizon and points close to the
/// sphere).
template <typename T>
struct sphere_light {
    using vec3 = glm::vec<3, T>;
    vec3 centre{T(0)};
    T radius{0};
    vec3 radiance{T(0)};

    // The light interface of ltc::shade (ltc/shading/lights/polygon_light.hpp).
    template <typename Policy>
    polygon_light_integrals<T> integrals(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                                         const shade_options&) const {
        polygon_light_integrals<T> I;
        const sphere_view<T> view = view_sphere(P, centre, radius);
        if (!frame.valid || view.kind == sphere_view<T>::nothing) return I;
        if (view.kind == sphere_view<T>::disk)
            return disk_light<T>::integrals(frame, P, m_inv, view.centre, view.normal, view.radius, sidedness::one_sided);
        // Inside or on the sphere: every direction (D and the clamped cosine integrate to 1).
        I.form_factor = I.ltc = T(1);
        return I;
    }
    template <typename Policy>
    T ltc_integral(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                   const shade_options& o) const {
        return integrals<Policy>(frame, P, m_inv, o).ltc;
    }
    vec3 emitted(const vec3& scale, T integral) const { return radiance * scale * integral; }
};

LTC_NAMESPACE_END
