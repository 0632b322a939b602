// ltc/shading/line_light.hpp -- shading a point with a constant-radiance tube (line) light and
// GGX: Heitz and Hill 2017's line lights, the LTC integral of a thin cylinder around the segment
// p0-p1 (ltc/core/line_integral.hpp) times its diameter.
//
//   ltc::polygon_light_result<float> r = ltc::shade_line_light(
//       P, N, V, roughness, F0, albedo, radiance, p0, p1, radius);
//
// Inputs as shade_polygon_light (ltc/shading/polygon_light.hpp), in world space, and the tube:
// its axis p0-p1 and radius. A tube glows all around: no sidedness; no end caps.
//
//   diffuse  = albedo * radiance * 2 r I_line,cos                   (integrate_line_cosine)
//   specular = radiance * (F0 magnitude + (1 - F0) fresnel) * 2 r I_line   (integrate_line)
//
// I_line is exact in the limit of a thin tube (r small against the distance to the point: the
// cylinder's solid angle is 2r d/|x|^3 dl + O(r^2) per axis element); a point close to the tube
// (distance ~ r) sees it wider than that, an error examples/shape_error_report measures against
// Monte Carlo of the real cylinder, with the GGX fit's. Degenerate input gives finite results:
// radius <= 0, p0 = p1, N = 0, an axis through the shading point give 0.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/line_integral.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/polygon_light_radiance.hpp>  // polygon_light_result, shade_polygon_light(frame, lobe, ...)
#include <ltc/shading/shading_frame.hpp>

#include <glm/glm.hpp>

#include <limits>

LTC_NAMESPACE_BEGIN

/// The tube light (file comment) with explicit LTC coefficients in the local frame of `frame`.
template <typename T>
inline polygon_light_result<T> shade_line_light(const shading_frame<T>& frame, const ltc_coefficients<T>& lobe,
                                                const glm::vec<3, T>& P, const glm::vec<3, T>& F0,
                                                const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                const glm::vec<3, T>& p0, const glm::vec<3, T>& p1, T radius) {
    polygon_light_result<T> r;
    if (!frame.valid || !(radius > T(0)) || !(radius <= std::numeric_limits<T>::max())) return r;
    const glm::vec<3, T> a = frame.to_local(p0 - P), b = frame.to_local(p1 - P);
    const auto spec = transformed<clamped_cosine<T>>::from_inverse(lobe.m_inv);
    const glm::vec<3, T> specular_scale = brdf_scale(F0, lobe);
    // 2 r I, saturated at the largest finite value (a huge r times I; 0 times an infinite 2r
    // would be NaN).
    const auto width = [&](T i) {
        if (!(i > T(0))) return T(0);
        const T w = radius * i;
        return w < std::numeric_limits<T>::max() / T(2) ? T(2) * w : std::numeric_limits<T>::max();
    };
    r.specular = radiance * specular_scale * width(integrate_line(spec, a, b));
    r.diffuse = albedo * radiance * width(integrate_line_cosine(a, b));
    return r;
}

/// The tube light (file comment) with the library's one-lobe GGX table (ltc::ggx::fetch).
template <typename T>
inline polygon_light_result<T> shade_line_light(const glm::vec<3, T>& P, const glm::vec<3, T>& N,
                                                const glm::vec<3, T>& V, T roughness, const glm::vec<3, T>& F0,
                                                const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                const glm::vec<3, T>& p0, const glm::vec<3, T>& p1, T radius) {
    const shading_frame<T> frame = make_shading_frame(N, V);
    return shade_line_light(frame, ggx::fetch<T>(frame.cos_theta_v, roughness), P, F0, albedo, radiance, p0, p1,
                            radius);
}

LTC_NAMESPACE_END
