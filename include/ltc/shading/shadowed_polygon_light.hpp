// ltc/shading/shadowed_polygon_light.hpp -- a polygonal light with shadows: the analytic LTC
// shading (ltc/shading/polygon_light.hpp) times a stochastic visibility ratio, the ratio
// estimator of Heitz, Hill and McGuire ("Combining Analytic Direct Illumination and Stochastic
// Shadows", I3D 2018, eq. 4):
//
//   shadowed ~= unshadowed_LTC * (sum_k f(w_k) V(w_k) / p(w_k)) / (sum_k f(w_k) / p(w_k))
//
// over K directions w_k towards the light, V the visibility given by the renderer.
//
//   auto r = ltc::shade_polygon_light_shadowed(P, N, V, roughness, F0, albedo, radiance,
//                                              vertices, n, ltc::sidedness::one_sided,
//                                              [&](glm::vec3 o, glm::vec3 d, float t) {
//                                                  return !scene.occluded(o, d, t); },
//                                              ltc::shadow_options<float>{16, per_pixel_shift});
//   glm::vec3 colour = r.ratio.specular + r.ratio.diffuse;
//
// Samples (shadow_sampler):
//   ltc_polygon  specular: w_k from the LTC restricted to the polygon, density D / I_D
//                (ltc/core/ltc_polygon_sampling.hpp, exact); diffuse: the clamped cosine
//                restricted to the polygon, density cos / E (the same sampler with M = I).
//                Where the light is unoccluded the ratio is exactly 1 (the analytic result is
//                returned without noise), and for the diffuse term f / p is constant, so its
//                ratio is the visible fraction of the samples, with no other noise.
//                2K visibility queries (K when the albedo is zero).
//   light_area   one set of K points uniform on the light's area (ltc/core/polygon_area_sampling.hpp)
//                shared by both terms, density |x - P|^2 / (A |cos theta_x|): the common
//                renderer baseline. K queries.
// f is the true BRDF, not its LTC: the GGX lobe without Fresnel (ltc/fitting/brdf/ggx.hpp,
// alpha = roughness^2) for the specular term, cos / pi for the diffuse one; the ratio corrects
// the analytic result for visibility only. The directions are a rank-1 lattice, (k + 1/2) / K
// and k / phi (the golden ratio) modulo 1, shifted by options.rotation (Cranley-Patterson
// rotation: pass a random shift per pixel to turn the structured error into noise).
//
// Outputs: `unshadowed` (= shade_polygon_light, horizon clipping ltc_space), `ratio` (the
// estimator above: biased, consistent, exact when nothing occludes the light) and `unbiased`
// (plain Monte Carlo of the true BRDF, Schlick's Fresnel included, with the same samples and
// visibility: (1/K) sum f V / p, for comparison; it carries the BRDF's noise instead of the
// LTC's fitting error). A light that faces away (one-sided) or lies below the horizon gives 0
// and makes no queries.
//
// Visibility callback: bool visible(origin, unit direction, distance), all world space, the
// distance measured to the light's plane along the direction; offset origin and distance by the
// renderer's own epsilon. The light: a convex planar polygon of at most 8 vertices.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/ltc_polygon_sampling.hpp>
#include <ltc/core/polygon_area_sampling.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>
#include <ltc/fitting/brdf/ggx.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/polygon_light.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

namespace ltc {

enum class shadow_sampler { ltc_polygon, light_area };

template <typename T>
struct shadow_options {
    std::size_t samples = 4;        ///< K: directions per lobe
    glm::vec<2, T> rotation{T(0)};  ///< Cranley-Patterson shift in [0, 1)^2, random per pixel
    shadow_sampler sampler = shadow_sampler::ltc_polygon;
};

template <typename T>
struct shadowed_polygon_light_result {
    polygon_light_result<T> unshadowed;  ///< analytic LTC, no visibility
    polygon_light_result<T> ratio;       ///< Heitz et al. 2018's ratio estimator
    polygon_light_result<T> unbiased;    ///< Monte Carlo of the true BRDF with the same samples
    std::size_t rays = 0;                ///< visibility queries made
};

namespace detail {

/// The k-th point of the shifted rank-1 lattice ((k + 1/2) / K, k / phi) mod 1.
template <typename T>
LTC_HOST_DEVICE inline glm::vec<2, T> lattice_point(std::size_t k, std::size_t count, const glm::vec<2, T>& shift) {
    const T x = (T(k) + T(0.5)) / T(count) + shift.x;
    const T y = T(0.6180339887498949) * T(k) + shift.y;
    return glm::vec<2, T>(x - std::floor(x), y - std::floor(y));
}

/// Running sums of the estimators for one term: sum f / p, sum f V / p and sum f F V / p.
template <typename T>
struct ratio_sums {
    T weights{0}, visible{0};
    glm::vec<3, T> unbiased{T(0)};
    LTC_HOST_DEVICE void add(T f_over_p, const glm::vec<3, T>& fresnel, bool seen) {
        weights += f_over_p;
        if (!seen) return;
        visible += f_over_p;
        unbiased += f_over_p * fresnel;
    }
    /// The visibility ratio: 1 (the analytic result) when no sample carried weight.
    LTC_HOST_DEVICE T ratio() const { return weights > T(0) ? visible / weights : T(1); }
};

}  // namespace detail

/// Shading of a constant-radiance polygonal light with visibility (file comment): the GGX
/// table's lobe at (N.V, roughness), world-space inputs as ltc::shade_polygon_light.
template <typename T, typename Visible>
shadowed_polygon_light_result<T> shade_polygon_light_shadowed(
    const glm::vec<3, T>& P, const glm::vec<3, T>& N, const glm::vec<3, T>& V, T roughness,
    const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
    const glm::vec<3, T>* vertices, std::size_t n, sidedness side, Visible&& visible,
    const shadow_options<T>& options = {}) {
    using vec3 = glm::vec<3, T>;
    constexpr std::size_t max_vertices = 8;
    shadowed_polygon_light_result<T> r;
    const shading_frame<T> frame = make_shading_frame(N, V);
    if (!frame.valid || n < 3 || n > max_vertices) return r;
    const ltc_coefficients<T> lobe = ggx::fetch<T>(frame.cos_theta_v, roughness);
    r.unshadowed = shade_polygon_light(frame, lobe, P, F0, albedo, radiance, vertices, n, side);
    const bool diffuse = albedo != vec3(T(0));
    if (r.unshadowed.specular == vec3(T(0)) && r.unshadowed.diffuse == vec3(T(0))) return r;

    vec3 local[max_vertices];
    for (std::size_t i = 0; i < n; ++i) local[i] = frame.to_local(vertices[i] - P);
    const polygon_area_sampler<T, max_vertices> plane(vertices, n);
    const vec3 v_local(detail::safe_sqrt(T(1) - frame.cos_theta_v * frame.cos_theta_v), T(0), frame.cos_theta_v);
    const T alpha = roughness * roughness;
    const auto to_world = [&](const vec3& w) { return frame.t1 * w.x + frame.t2 * w.y + frame.n * w.z; };
    // Distance along the unit world direction d to the light's plane.
    const auto distance = [&](const vec3& d) {
        const T c = glm::dot(d, plane.normal());
        return c != T(0) ? glm::dot(vertices[0] - P, plane.normal()) / c : T(0);
    };
    const auto fresnel = [&](const vec3& l) {  // Schlick, with V.H of the half vector
        const vec3 h = detail::safe_normalize(v_local + l);
        const T m = T(1) - glm::clamp(glm::dot(v_local, h), T(0), T(1));
        const T m2 = m * m;
        return F0 + (vec3(T(1)) - F0) * (m2 * m2 * m);
    };
    const auto query = [&](const vec3& l_world, T t) {
        ++r.rays;
        return t > T(0) && static_cast<bool>(visible(P, l_world, t));
    };

    detail::ratio_sums<T> spec, diff;
    const std::size_t K = options.samples;
    if (options.sampler == shadow_sampler::ltc_polygon) {
        const ltc_polygon_sampler<T, max_vertices> lobe_sampler(transformed<clamped_cosine<T>>::from_inverse(lobe.m_inv),
                                                                local, n);
        const projected_polygon_sampler<T, max_vertices> cosine_sampler(local, n);
        for (std::size_t k = 0; k < K; ++k) {
            const glm::vec<2, T> u = detail::lattice_point(k, K, options.rotation);
            if (!lobe_sampler.empty()) {
                const polygon_sample<T> x = lobe_sampler.sample(u);
                if (x.pdf > T(0)) {
                    const vec3 d = to_world(x.direction);
                    const bool seen = query(d, distance(d));
                    spec.add(brdf::ggx<T>::eval(v_local, x.direction, alpha) / x.pdf, fresnel(x.direction), seen);
                }
            }
            if (diffuse && !cosine_sampler.empty()) {
                const polygon_sample<T> x = cosine_sampler.sample(u);
                if (x.pdf > T(0)) {
                    const vec3 d = to_world(x.direction);
                    diff.add(x.direction.z / pi<T>() / x.pdf, vec3(T(1)), query(d, distance(d)));
                }
            }
        }
    } else {
        for (std::size_t k = 0; k < K && !plane.empty(); ++k) {
            const vec3 x = plane.sample(detail::lattice_point(k, K, options.rotation));
            const T p = plane.solid_angle_pdf(P, x);
            if (!(p > T(0))) continue;
            const vec3 d = detail::safe_normalize(x - P);
            const vec3 l = frame.to_local(d);
            const bool seen = query(d, glm::length(x - P));
            spec.add(brdf::ggx<T>::eval(v_local, l, alpha) / p, fresnel(l), seen);
            if (diffuse) diff.add(glm::max(l.z, T(0)) / pi<T>() / p, vec3(T(1)), seen);
        }
    }

    r.ratio.specular = r.unshadowed.specular * spec.ratio();
    r.ratio.diffuse = r.unshadowed.diffuse * diff.ratio();
    if (K > 0) {
        const T inv_k = T(1) / T(K);
        r.unbiased.specular = radiance * spec.unbiased * inv_k;
        r.unbiased.diffuse = albedo * radiance * (diff.visible * inv_k);
    }
    return r;
}

}  // namespace ltc
