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
// Samples (shadow_sampler), K in all (on average, with rejection), one visibility query each (none
// for a sample below the surface, where both integrands vanish), every sample serving both terms:
//   ltc_polygon  the specular share from the LTC restricted to the polygon, density D / I_D:
//                where the light holds at least options.rejection_from (1/8) of the lobe, by
//                rejection: N = K_s / I_D draws of the whole LTC (Algorithm 1: no sampler to
//                build), those that hit the light kept (K_s on average, no query for the
//                others); elsewhere by the exact sampler (ltc/core/ltc_polygon_sampling.hpp).
//                The diffuse share from options.diffuse: light_area (the default: uniform on the
//                light) or cosine (the clamped cosine restricted to the polygon, exact, density
//                cos / E: ltc/core/projected_solid_angle_sampling.hpp; ~8x the cost of an area
//                sample in bench_sampling, for constant diffuse weights where area samples' vary
//                most: lights close to or grazing the surface). K_s and K_d are in proportion to
//                the specular and diffuse shares of the analytic result (with the cosine lobe,
//                below, its LTC's part and the rest), and every sample is weighted by the balance
//                heuristic over the whole plan (multi-sample MIS, Veach 1997 eq. 9.13:
//                f / (K_s D / I_D + K_d p_d), or f / (N D + K_d p_d) with rejection; the
//                normalizers in closed form). Where the light is unoccluded the ratio is exactly
//                1 (the analytic result, without noise); where the LTC takes all the samples,
//                f / p varies only by the GGX/LTC mismatch, so the ratio is close to the
//                visible fraction of the samples.
//   light_area   K points uniform on the light's area (ltc/core/polygon_area_sampling.hpp),
//                density |x - P|^2 / (A |cos theta_x|), for both terms: the common renderer
//                baseline.
// f is the true BRDF, not its LTC: the GGX lobe without Fresnel (ltc/brdf/ggx.hpp,
// alpha = roughness^2) for the specular term, cos / pi for the diffuse one; the ratio corrects
// the analytic result for visibility only. The directions are a rank-1 lattice, (k + 1/2) / n
// and k / phi (the golden ratio) modulo 1, n the sampler's own count, shifted by options.rotation
// (Cranley-Patterson rotation: pass a random shift per pixel to turn the structured error into
// noise). Where a renderer filters the estimates over neighbouring pixels, the shifts can instead
// be stratified across pixels: options.rotation = ltc::screen_point(x, y, image_seed) with
// options.stratified_rotation, which shifts each technique's lattice of n points by rotation.x / n,
// one period of its first coordinate, so that the n 4^k first coordinates of an aligned
// 2^k x 2^k block of pixels with the same n fall one per interval of width 1 / (n 4^k) (a shift
// by rotation.x itself stratifies nothing but the points' common offset; a shift by
// rotation.x / K, K the total count, would cover only part of the periods of a technique whose n
// is not a multiple of K, and bias its sums).
// Each sum keeps its expectation over a uniform rotation (the n intervals of width 1 / n that
// the first coordinates sweep tile [0, 1)); the ratio, a nonlinear function of them, is not
// distributed exactly as with random shifts. In the shadows example the denoised result's mean
// error at K = 1 / 4 / 16 falls from 5.4 / 3.4 / 1.9% (random shifts, four seeds' mean) to
// 4.2 / 2.7 / 1.8% (README, "Shadows").
//
// The analytic part is by default the one-lobe shading (shade_polygon_light_one_lobe: with the
// ratio, the tables measured alike at equal time, README "Shadows"), with options.lobes =
// analytic_lobes::two the opt-in two-lobe table's (ltc/shading/two_lobe_polygon_light.hpp): the
// ratio then corrects a closer unshadowed result (the shadows example: RMS bias against the
// path-traced truth 10.7% with one lobe, 4.3% with two, at K = 16), at the cost of its second
// lobe's integral; the samples then follow its first lobe (sampling the two lobes' mixture
// measured worse at equal CPU time: README, shadows section). With analytic_lobes::cosine_lobe,
// the table of an LTC and the clamped cosine that ltc::shade_polygon_light uses
// (ltc/shading/cosine_lobe_polygon_light.hpp: no second integral; RMS bias 5.6% there): K_s
// follows its LTC's part of the specular term only, and the cosine's part joins the diffuse share
// (K_d), whose technique covers the broad part that the LTC, fitted next to the cosine, leaves out.
//
// Outputs: `unshadowed` (= shade_polygon_light_one_lobe, shade_polygon_light_two_lobe or
// shade_polygon_light_cosine_lobe, the last ltc::shade_polygon_light; horizon clipping ltc_space),
// `ratio` (the estimator above: biased, consistent, exact when nothing occludes the light),
// `unbiased` (plain Monte Carlo of the true BRDF, Schlick's Fresnel included, with the same
// samples and visibility: sum f V / (sum_k n_k p_k), for comparison; it carries the BRDF's noise instead of the LTC's
// fitting error), and per term the ratio's two sums (`specular_estimates`, `diffuse_estimates`),
// for renderers that denoise the shadows as Heitz et al. do: filter each of the two over
// neighbouring pixels, then ltc::ratio_shading, so that the filter blurs the visibility only,
// never the analytic shading. Each term's estimates also carry the analytic part's value of what
// `total` estimates (the LTC's integral of f; the form factor for the diffuse term), and
// `specular_fresnel_estimates` the same for f (1 - V.H)^5, Schlick's (1 - F0) part: with them,
// ltc::corrected_specular corrects the LTC's fitting error as well as the shadows (the filtered
// estimate of the shadowed integral relative to the analytic one, per part of Hill's Fresnel
// split; in the shadows example, with random rotations, it cut the denoised result's mean error
// from 4.9% to 3.3% at K = 4, and on the gold tiles, where the LTC is 8% off, from 11.4% to 4.0%). A light that
// faces away (one-sided) or lies below the horizon gives 0 and makes no queries; K = 0 gives the
// analytic result.
//
// Visibility callback: bool visible(origin, unit direction, distance), all world space, the
// distance measured to the light's plane along the direction; offset origin and distance by the
// renderer's own epsilon; its answer is converted to bool. Or, from a closest-hit query,
// ltc::first_hit(callback), callback returning the distance t_b to the first occluder along the
// direction (a floating-point value; `distance` or more, or +inf, where nothing occludes): the
// sample is occluded where t_b < distance (a NaN is not; a negative t_b counts as 0), and the
// result's `blockers` then sums t_b / (t_l - t_b) over the occluded samples, t_l = distance: the
// estimate of a penumbra's width of percentage-closer soft shadows (penumbra_width; Fernando,
// SIGGRAPH 2005), with which a renderer that filters the estimates can narrow its filter where
// the penumbra is narrow (the shadows example's (d)). The wrapper makes the distance explicit: a
// callback that returns a float visibility or transmittance stays a boolean one. The light: a
// convex planar polygon of at most 8 vertices.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/ltc_polygon_sampling.hpp>
#include <ltc/core/polygon_area_sampling.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>
#include <ltc/core/screen_order.hpp>
#include <ltc/brdf/ggx.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/cosine_lobe_polygon_light.hpp>
#include <ltc/shading/two_lobe_polygon_light.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

LTC_NAMESPACE_BEGIN

enum class shadow_sampler { ltc_polygon, light_area };
/// The diffuse share's technique under shadow_sampler::ltc_polygon (file comment).
enum class diffuse_sampler { light_area, cosine };
/// The analytic, unshadowed part: the one-lobe GGX table's lobe (the default here), the opt-in
/// two-lobe table (ltc/shading/two_lobe_polygon_light.hpp; the samples then follow its first lobe,
/// which the estimator only needs as a density) or the table of an LTC and the cosine, which
/// ltc::shade_polygon_light uses (ltc/shading/cosine_lobe_polygon_light.hpp; the specular
/// samples follow its LTC, for the LTC's part of the specular term; the cosine's part joins the
/// diffuse share).
enum class analytic_lobes { one, two, cosine_lobe };

template <typename T>
struct shadow_options {
    std::size_t samples = 4;        ///< K: directions (visibility queries) per call
    /// Cranley-Patterson shift in [0, 1)^2, per pixel: random, or ltc::screen_point with stratified_rotation
    glm::vec<2, T> rotation{T(0)};
    /// Each technique's lattice of n points shifted by rotation.x / n along its first coordinate,
    /// which repeats every 1 / n, instead of by rotation.x: for rotations stratified across pixels
    /// (ltc::screen_point of ltc/core/screen_order.hpp), so that a block of pixels' lattices of one
    /// n are stratified together (file comment). Either way each sum keeps its expectation for a
    /// uniform rotation.
    bool stratified_rotation = false;
    shadow_sampler sampler = shadow_sampler::ltc_polygon;
    diffuse_sampler diffuse = diffuse_sampler::light_area;
    T rejection_from{T(0.125)};     ///< I_D from which the LTC share is drawn by rejection (> 1: never)
    analytic_lobes lobes = analytic_lobes::one;
};

/// One term's two Monte Carlo estimates over the same samples (the balance heuristic's sums,
/// sum_k f(w_k) [V(w_k)] / sum_j n_j p_j(w_k)): of the integrals over the light of f V (`visible`)
/// and of f (`total`), f the term's BRDF without Fresnel and radiance (for
/// specular_fresnel_estimates, times (1 - V.H)^5); unbiased where the sample plan's density covers
/// the part of the light where f > 0 (the light-area share covers all of it; an LTC share alone
/// only its lobe's support), 0 where no sample is drawn; and the analytic part's value of the
/// integral of f (`analytic`, set whenever the light is shaded, samples or not). Their ratio is
/// the term's visibility ratio (ratio_shading). Since the plan's counts n_j are in the
/// denominator, their expectations do not depend on K: a renderer that denoises shadows filters
/// each of the two over neighbouring pixels, whatever their K, and takes the ratio of the filtered
/// values (Heitz et al. 2018: the noise is then blurred in the shadows only, never in the
/// analytic shading).
template <typename T>
struct ratio_estimates {
    T visible{0};   ///< estimate of the integral of f V over the light
    T total{0};     ///< estimate of the integral of f over the light
    T analytic{0};  ///< the analytic part's value of what `total` estimates (the LTC's; exact for the diffuse term)
};

/// The occluded samples' blockers, from a first-hit visibility callback (file comment): over
/// the samples whose query met an occluder at t_b < t_l (t_l the light's plane's distance along
/// the ray), the sum of t_b / (t_l - t_b) and their number. Both are sums, so a renderer can
/// filter them over neighbouring pixels (weighted: `occluded` need not stay an integer) before
/// penumbra_width, as it filters ratio_estimates. 0 and 0 for a boolean callback.
template <typename T>
struct blocker_estimates {
    T ratio_sum{0};  ///< sum over the occluded samples of t_b / (t_l - t_b)
    T occluded{0};   ///< the occluded samples
};

/// A visibility callback that answers with the first occluder's distance (file comment): what
/// ltc::first_hit wraps. Calls the callback as it is, const or not (a mutable lambda, as an
/// unwrapped callback may be).
template <typename F>
struct first_hit_callback {
    F callback;
    template <typename... A>
    LTC_HOST_DEVICE auto operator()(A&&... a) -> decltype(callback(std::forward<A>(a)...)) {
        return callback(std::forward<A>(a)...);
    }
    template <typename... A>
    LTC_HOST_DEVICE auto operator()(A&&... a) const -> decltype(static_cast<const F&>(callback)(std::forward<A>(a)...)) {
        return callback(std::forward<A>(a)...);
    }
};

/// Marks `callback(origin, unit direction, distance)` as returning the first occluder's distance
/// along the ray (+inf where none) instead of a visibility: shade_polygon_light_shadowed then
/// records the occluded samples' blockers (blocker_estimates).
template <typename F>
LTC_HOST_DEVICE inline first_hit_callback<std::decay_t<F>> first_hit(F&& callback) {
    return {std::forward<F>(callback)};
}

namespace detail {
template <typename F>
struct is_first_hit : std::false_type {};
template <typename F>
struct is_first_hit<first_hit_callback<F>> : std::true_type {};
}  // namespace detail

/// Percentage-closer soft shadows' penumbra width (Fernando, "Percentage-Closer Soft Shadows",
/// SIGGRAPH 2005 sketch, by similar triangles: an occluder edge at t_b from the point, towards a
/// light of extent w_l across the edge at t_l, casts a penumbra w_l t_b / (t_l - t_b) wide on a
/// receiver parallel to the light and the occluder), with t_b / (t_l - t_b) averaged over the
/// occluded samples: light_extent times blockers.ratio_sum / blockers.occluded, in the units of
/// light_extent; 0 where no sample was occluded.
template <typename T>
LTC_HOST_DEVICE inline T penumbra_width(T light_extent, const blocker_estimates<T>& blockers) {
    return blockers.occluded > T(0) ? light_extent * (blockers.ratio_sum / blockers.occluded) : T(0);
}

template <typename T>
struct shadowed_polygon_light_result {
    polygon_light_result<T> unshadowed;  ///< analytic LTC, no visibility
    polygon_light_result<T> ratio;       ///< Heitz et al. 2018's ratio estimator
    polygon_light_result<T> unbiased;    ///< Monte Carlo of the true BRDF with the same samples
    std::size_t rays = 0;                ///< visibility queries made
    ratio_estimates<T> specular_estimates;  ///< the specular ratio's two sums and analytic value (for denoising)
    ratio_estimates<T> diffuse_estimates;   ///< the diffuse ratio's two sums and analytic value (for denoising)
    /// The specular sums with f (1 - V.H)^5, Schlick's (1 - F0) part, its analytic value the
    /// tables' Fresnel channel times the LTC integral (for corrected_specular).
    ratio_estimates<T> specular_fresnel_estimates;
    /// The occluded samples' blocker distances, with a first-hit callback (file comment).
    blocker_estimates<T> blockers;
};

/// The ratio estimator's term from its analytic value and the two estimates of its visibility
/// ratio (Heitz et al. 2018, eq. 4): analytic * visible / total, the analytic term itself where
/// the total is not positive (no sample carried weight). Takes filtered (denoised) estimates as
/// well as one pixel's.
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> ratio_shading(const glm::vec<3, T>& analytic, const ratio_estimates<T>& e) {
    return e.total > T(0) ? analytic * (e.visible / e.total) : analytic;
}

/// Both terms: the analytic, unshadowed result (shadowed_polygon_light_result::unshadowed) and
/// each term's two estimates, filtered or not.
template <typename T>
LTC_HOST_DEVICE inline polygon_light_result<T> ratio_shading(const polygon_light_result<T>& analytic,
                                                             const ratio_estimates<T>& specular,
                                                             const ratio_estimates<T>& diffuse) {
    polygon_light_result<T> r;
    r.specular = ratio_shading(analytic.specular, specular);
    r.diffuse = ratio_shading(analytic.diffuse, diffuse);
    return r;
}

/// The specular term with the LTC's fitting error corrected as well as the shadows, from the
/// sums of both parts of Schlick's Fresnel factor, F0 f + (1 - F0) f (1 - V.H)^5 (Hill's split,
/// brdf_scale): per part j, the pixel's own analytic value a_j times the ratio of the estimate
/// of the integral of f_j V to its analytic value, both filtered over neighbouring pixels:
///
///   radiance * (F0 a_0 visible_0 / analytic_0 + (1 - F0) a_1 visible_1 / analytic_1).
///
/// The filter then averages the Monte Carlo estimate of the true, shadowed integral relative to
/// the LTC's, which tracks its variation over the image: a renderer's denoiser demodulated by the
/// analytic shading. Unlike ratio_shading, it is not exact where nothing occludes the light (the
/// estimates of f / LTC's mismatch stay, filtered), and it converges to the GGX lobe with
/// Schlick's factor instead of the LTC. Unfiltered, it is the unbiased estimate of the result
/// (shadowed_polygon_light_result::unbiased) up to rounding. A part whose analytic value is
/// not positive gives 0, and so does K = 0 (no visible sums: ratio_shading gives the analytic
/// term instead). own / analytic is taken first: the filtered analytic value holds the pixel's
/// own with a positive weight, so the quotient stays bounded where a tiny float analytic value
/// would make visible / analytic overflow.
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> corrected_specular(const glm::vec<3, T>& F0, const glm::vec<3, T>& radiance,
                                                         T own_analytic, T own_analytic_fresnel,
                                                         const ratio_estimates<T>& specular,
                                                         const ratio_estimates<T>& specular_fresnel) {
    const T s0 = specular.analytic > T(0) ? specular.visible * (own_analytic / specular.analytic) : T(0);
    const T s1 = specular_fresnel.analytic > T(0)
                     ? specular_fresnel.visible * (own_analytic_fresnel / specular_fresnel.analytic)
                     : T(0);
    return radiance * (F0 * s0 + (glm::vec<3, T>(T(1)) - F0) * s1);
}

namespace detail {

/// The k-th point of the shifted rank-1 lattice ((k + 1/2) / K + s_x, k / phi + s_y) mod 1, or with
/// `per_period` ((k + 1/2 + s_x) / K, k / phi + s_y) mod 1 (shadow_options::stratified_rotation).
template <typename T>
LTC_HOST_DEVICE inline glm::vec<2, T> lattice_point(std::size_t k, std::size_t count, const glm::vec<2, T>& shift,
                                                    bool per_period = false) {
    const T x = per_period ? (T(k) + T(0.5) + shift.x) / T(count) : (T(k) + T(0.5)) / T(count) + shift.x;
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
    LTC_HOST_DEVICE ratio_estimates<T> estimates(T analytic) const { return {visible, weights, analytic}; }
};

}  // namespace detail

/// Shading of a constant-radiance polygonal light with visibility (file comment): the GGX
/// table's lobe at (N.V, roughness) (options.lobes: which table), world-space inputs as
/// ltc::shade_polygon_light.
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
    // The sampled lobe: the GGX table's, with two lobes the first (the second adds its term:
    // shade_polygon_light_two_lobe's bits, without a second form factor), with the cosine the
    // LTC (the cosine adds its term from the form factor: shade_polygon_light_cosine_lobe's bits).
    const bool two = options.lobes == analytic_lobes::two, cosine_lobe = options.lobes == analytic_lobes::cosine_lobe;
    const std::array<ltc_coefficients<T>, 2> lobes =
        two           ? ggx_two_lobe::fetch<T>(frame.cos_theta_v, roughness)
        : cosine_lobe ? ggx_cosine_lobe::fetch<T>(frame.cos_theta_v, roughness)
                      : std::array<ltc_coefficients<T>, 2>{ggx::fetch<T>(frame.cos_theta_v, roughness), ltc_coefficients<T>{}};
    const ltc_coefficients<T>& lobe = lobes[cosine_lobe ? 1 : 0];
    const polygon_light_integrals<T> I = integrate_polygon_light<edge_policy::automatic>(frame, lobe.m_inv, P, vertices, n);
    r.unshadowed = polygon_light_radiance(I, lobe, F0, albedo, radiance, side);
    const vec3 sampled_lobe = r.unshadowed.specular;
    // The analytic values of the integrals of f and f (1 - V.H)^5: each lobe's magnitude and
    // Fresnel channel times its integral (second_lobe_specular's bits, one integral).
    const T ltc_integral = apply_sidedness(I.ltc, side), form_factor = apply_sidedness(I.form_factor, side);
    T analytic_f = lobe.magnitude * ltc_integral, analytic_fresnel = lobe.fresnel * ltc_integral;
    if (two) {
        const T second = apply_sidedness(integrate_polygon_light_ltc(frame, lobes[1].m_inv, P, vertices, n), side);
        r.unshadowed.specular += radiance * brdf_scale(F0, lobes[1]) * second;
        analytic_f += lobes[1].magnitude * second;
        analytic_fresnel += lobes[1].fresnel * second;
    }
    if (cosine_lobe) {
        r.unshadowed.specular += radiance * brdf_scale(F0, lobes[0]) * form_factor;
        analytic_f += lobes[0].magnitude * form_factor;
        analytic_fresnel += lobes[0].fresnel * form_factor;
    }
    r.specular_estimates.analytic = analytic_f;
    r.specular_fresnel_estimates.analytic = analytic_fresnel;
    r.diffuse_estimates.analytic = form_factor;
    r.ratio = r.unshadowed;
    const T weight_s = r.unshadowed.specular.x + r.unshadowed.specular.y + r.unshadowed.specular.z;
    const T weight_d = r.unshadowed.diffuse.x + r.unshadowed.diffuse.y + r.unshadowed.diffuse.z;
    // The LTC technique's share: the specular term, or with the cosine lobe its LTC's part only
    // (the cosine's part goes with the diffuse term to the diffuse technique, the light's area or
    // the cosine itself: the LTC, fitted next to the cosine, is narrower than GGX).
    const T weight_ltc = cosine_lobe ? sampled_lobe.x + sampled_lobe.y + sampled_lobe.z : weight_s;
    const std::size_t K = options.samples;
    if (!(weight_s + weight_d > T(0)) || K == 0) return r;

    vec3 local[max_vertices];
    for (std::size_t i = 0; i < n; ++i) local[i] = frame.to_local(vertices[i] - P);
    const polygon_area_sampler<T, max_vertices> plane(vertices, n);
    const vec3 v_local(detail::safe_sqrt(T(1) - frame.cos_theta_v * frame.cos_theta_v), T(0), frame.cos_theta_v);
    const T alpha = roughness * roughness;
    const auto d = transformed<clamped_cosine<T>>::from_inverse(lobe.m_inv);
    const T i_d = std::abs(I.ltc), e = pi<T>() * std::abs(I.form_factor);  // the two densities' normalizers

    // The callback's answer: visible, or with ltc::first_hit the first occluder's distance (file
    // comment), which adds its PCSS ratio to the blockers where the sample is occluded.
    const auto query = [&](const vec3& world, T distance) -> bool {
        if constexpr (detail::is_first_hit<std::decay_t<Visible>>::value) {
            static_assert(std::is_floating_point_v<std::decay_t<decltype(visible(P, world, distance))>>,
                          "ltc::first_hit: the callback returns the first occluder's distance, a floating-point value");
            const T t_b = static_cast<T>(visible(P, world, distance));
            if (!(t_b < distance)) return true;  // nothing before the light (a NaN too)
            const T t = glm::max(t_b, T(0));  // t < distance: the quotient is finite and >= 0
            r.blockers.ratio_sum += t / (distance - t);
            r.blockers.occluded += T(1);
            return false;
        } else {
            return static_cast<bool>(visible(P, world, distance));
        }
    };
    // Each direction l (local) with its density under the whole sample plan, sum_k n_k p_k(l) (the
    // balance heuristic's denominator, Veach 1997 eq. 9.13), adds f / density to both terms.
    detail::ratio_sums<T> spec, diff, schlick;
    const auto add = [&](const vec3& l, const vec3& world, T distance, T density) {
        // Below the surface both integrands are 0: no query (the sums would not change).
        if (!(density > T(0)) || !(l.z > T(0))) return;
        ++r.rays;
        const bool seen = distance > T(0) && query(world, distance);
        const vec3 h = detail::safe_normalize(v_local + l);  // Schlick's factor at V.H
        const T m = T(1) - glm::clamp(glm::dot(v_local, h), T(0), T(1));
        const T m5 = m * m * m * m * m;
        const vec3 fresnel = F0 + (vec3(T(1)) - F0) * m5;
        const T f_over_p = brdf::ggx<T>::eval(v_local, l, alpha) / density;
        spec.add(f_over_p, fresnel, seen);
        schlick.add(f_over_p * m5, vec3(T(0)), seen);
        diff.add(l.z / pi<T>() / density, vec3(T(1)), seen);
    };
    const auto to_world = [&](const vec3& w) { return frame.t1 * w.x + frame.t2 * w.y + frame.n * w.z; };
    // The k-th of a technique's `count` lattice points, shifted as the options ask.
    const auto lattice = [&](std::size_t k, std::size_t count) {
        return detail::lattice_point(k, count, options.rotation, options.stratified_rotation);
    };
    const auto plane_distance = [&](const vec3& w) {  // along the unit world direction w
        const T c = glm::dot(w, plane.normal());
        return c != T(0) ? glm::dot(vertices[0] - P, plane.normal()) / c : T(0);
    };

    if (options.sampler == shadow_sampler::ltc_polygon) {
        // Samples split between the two exact samplers in proportion to the terms' shares.
        std::size_t ks = static_cast<std::size_t>(std::lround(T(K) * weight_ltc / (weight_s + weight_d)));
        if (!(i_d > T(0))) ks = 0;
        if (!(e > T(0))) ks = K;
        const std::size_t kd = K - ks;
        const bool cosine = options.diffuse == diffuse_sampler::cosine;
        // Where the light holds at least 1/8 of the lobe, the restricted LTC by rejection: draws
        // of the whole LTC (Algorithm 1), those that hit the light kept (no query for the others).
        const bool reject = ks > 0 && i_d >= options.rejection_from && i_d > T(0);
        // At most 8 K_s draws, capped before the conversion: K_s / I_D overflows an integer
        // where I_D is tiny (options.rejection_from = 0; found by the fuzzer).
        const std::size_t draws =
            reject ? static_cast<std::size_t>(std::ceil(glm::min(T(8 * ks), T(ks) / i_d))) : ks;
        ltc_polygon_sampler<T, max_vertices> lobe_sampler;
        projected_polygon_sampler<T, max_vertices> cosine_sampler;
        if (ks > 0 && !reject) lobe_sampler = ltc_polygon_sampler<T, max_vertices>(d, local, n);
        if (kd > 0 && cosine) cosine_sampler = projected_polygon_sampler<T, max_vertices>(local, n);
        // The specular technique's density per draw at l: D(l) by rejection, else the exact
        // sampler's D(l) / I_D, its I_D its own (in float the shading's i_d, by the minimax edge
        // terms, can be far off where it is tiny): every technique's weight then uses the same
        // density, and an empty() sampler, which draws nothing, has density 0.
        const auto lobe_density = [&](const vec3& l) {
            return ks == 0 ? T(0) : reject ? d.eval(l) : lobe_sampler.pdf(l);
        };
        // The plan's density at l (world w, the light's plane at distance t along it), given lobe_density(l).
        const auto density = [&](const vec3& l, const vec3& w, T t, T lobe) {
            T p = T(draws) * lobe;
            if (kd > 0) p += T(kd) * (cosine ? glm::max(l.z, T(0)) / e : plane.solid_angle_pdf(P, P + w * t));
            return p;
        };
        const auto add_local = [&](const vec3& l, T lobe) {
            const vec3 w = to_world(l);
            const T t = plane_distance(w);
            add(l, w, t, density(l, w, t, lobe));
        };
        // A sample's pdf is lobe_density at its direction: no second evaluation of D.
        for (std::size_t k = 0; k < ks && !reject && !lobe_sampler.empty(); ++k) {
            const polygon_sample<T> x = lobe_sampler.sample(lattice(k, ks));
            add_local(x.direction, x.pdf);
        }
        if (reject) {
            // The light's great circles, pointing inwards (a convex polygon seen from P).
            vec3 edge[max_vertices];
            const T side = glm::dot(local[0], glm::cross(local[1] - local[0], local[2] - local[0])) < T(0) ? T(-1) : T(1);
            for (std::size_t i = 0; i < n; ++i) edge[i] = side * glm::cross(local[i], local[(i + 1) % n]);
            for (std::size_t k = 0; k < draws; ++k) {
                const vec3 l = d.sample(lattice(k, draws));
                bool hit = true;
                for (std::size_t i = 0; i < n && hit; ++i) hit = glm::dot(l, edge[i]) >= T(0);
                if (hit) add_local(l, lobe_density(l));
            }
        }
        for (std::size_t k = 0; k < kd && cosine && !cosine_sampler.empty(); ++k) {
            const vec3 l = cosine_sampler.sample(lattice(k, kd)).direction;
            add_local(l, lobe_density(l));
        }
        for (std::size_t k = 0; k < kd && !cosine && !plane.empty(); ++k) {
            const vec3 x = plane.sample(lattice(k, kd));
            const vec3 w = detail::safe_normalize(x - P);
            const vec3 l = frame.to_local(w);
            add(l, w, glm::length(x - P), density(l, w, glm::length(x - P), lobe_density(l)));
        }
    } else {
        for (std::size_t k = 0; k < K && !plane.empty(); ++k) {
            const vec3 x = plane.sample(lattice(k, K));
            const vec3 w = detail::safe_normalize(x - P);
            add(frame.to_local(w), w, glm::length(x - P), T(K) * plane.solid_angle_pdf(P, x));
        }
    }

    r.specular_estimates = spec.estimates(analytic_f);
    r.specular_fresnel_estimates = schlick.estimates(analytic_fresnel);
    r.diffuse_estimates = diff.estimates(form_factor);
    r.ratio = ratio_shading(r.unshadowed, r.specular_estimates, r.diffuse_estimates);
    r.unbiased.specular = radiance * spec.unbiased;
    r.unbiased.diffuse = albedo * radiance * diff.visible;
    return r;
}

LTC_NAMESPACE_END
