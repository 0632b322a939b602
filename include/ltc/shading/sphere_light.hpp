// ltc/shading/sphere_light.hpp -- shading a point with a constant-radiance sphere light and GGX,
// exactly: a sphere of radius R whose centre is at distance d > R covers the same directions as
// the disk facing the point through its circle of tangency (the base of the cone it subtends):
//
//   centre' = P + (C - P) (1 - R^2/d^2),  normal' = (P - C)/d,  radius' = R sqrt(1 - R^2/d^2),
//
// so its LTC integral is the disk's (ltc/shading/disk_light.hpp, exact to rounding), not an
// approximation: the method Blender EEVEE and the 2017 course (Heitz and Hill) use for spheres,
// with the exact disk integral. Uniform radiance, so only the directions matter.
//
//   ltc::polygon_light_result<float> r = ltc::shade_sphere_light(
//       P, N, V, roughness, F0, albedo, radiance, centre, radius);
//
// Inputs as shade_polygon_light (ltc/shading/polygon_light.hpp), in world space. The sphere
// glows all around: no sidedness. A shading point inside the sphere or on it (d <= R) sees it in
// every direction: the whole LTC, I = 1 (D integrates to 1), and E = 1; radius <= 0 or
// non-finite input gives 0. 1 - R^2/d^2 is computed
// as (d - R)(d + R)/d^2 (no cancellation for a point close to the sphere). The shading's error is
// the GGX fit's (examples/shape_error_report, including spheres straddling the horizon and
// points close to the sphere).
#pragma once

#include <ltc/config.hpp>

#include <ltc/shading/disk_light.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/polygon_light_radiance.hpp>  // polygon_light_result, shade_polygon_light(frame, lobe, ...)
#include <ltc/shading/shading_frame.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

LTC_NAMESPACE_BEGIN

/// What a sphere (centre, radius) is from P (file comment): `disk`, the disk that covers the
/// same directions; `inside` (d <= R: every direction); or `nothing` (radius <= 0 or NaN,
/// non-finite input).
template <typename T>
struct sphere_view {
    enum kind_t { nothing, disk, inside } kind = nothing;
    glm::vec<3, T> centre{T(0)}, normal{T(0), T(0), T(1)};
    T radius{0};
};

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

/// The sphere light (file comment) with explicit LTC coefficients in the local frame of `frame`.
template <typename T>
inline polygon_light_result<T> shade_sphere_light(const shading_frame<T>& frame, const ltc_coefficients<T>& lobe,
                                                  const glm::vec<3, T>& P, const glm::vec<3, T>& F0,
                                                  const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                  const glm::vec<3, T>& centre, T radius) {
    polygon_light_result<T> r;
    const sphere_view<T> view = view_sphere(P, centre, radius);
    if (!frame.valid || view.kind == sphere_view<T>::nothing) return r;
    if (view.kind == sphere_view<T>::disk)
        return shade_disk_light(frame, lobe, P, F0, albedo, radiance, view.centre, view.normal, view.radius,
                                sidedness::one_sided);
    // Inside or on the sphere: every direction (D and the clamped cosine integrate to 1).
    r.specular = radiance * brdf_scale(F0, lobe);
    r.diffuse = albedo * radiance;
    return r;
}

/// The sphere light (file comment) with the library's one-lobe GGX table (ltc::ggx::fetch).
template <typename T>
inline polygon_light_result<T> shade_sphere_light(const glm::vec<3, T>& P, const glm::vec<3, T>& N,
                                                  const glm::vec<3, T>& V, T roughness, const glm::vec<3, T>& F0,
                                                  const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                  const glm::vec<3, T>& centre, T radius) {
    const shading_frame<T> frame = make_shading_frame(N, V);
    return shade_sphere_light(frame, ggx::fetch<T>(frame.cos_theta_v, roughness), P, F0, albedo, radiance, centre,
                              radius);
}

LTC_NAMESPACE_END
