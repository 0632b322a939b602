// ltc/shading/shade_shadowed.hpp -- a polygonal light with shadows: the analytic LTC shading of
// ltc::shade (ltc/shading/shade.hpp) times a stochastic visibility ratio, the ratio estimator of
// Heitz, Hill and McGuire ("Combining Analytic Direct Illumination and Stochastic Shadows",
// I3D 2018, eq. 4), over K directions w_k towards the light, V the renderer's visibility:
//
//   shadowed ~= unshadowed_LTC * (sum_k f(w_k) V(w_k) / p(w_k)) / (sum_k f(w_k) / p(w_k))
//
//   auto quad = ltc::polygon_light<float>::one_sided(vertices, 4, emission_normal, radiance);
//   auto r = ltc::shade_shadowed(surface, quad, [&](glm::vec3 o, glm::vec3 d, float t) { return !scene.occluded(o, d, t); },
//                                ltc::shadow_sampling<float>{16, per_pixel_shift});  // ggx::ltc_and_cosine
//   glm::vec3 colour = r.ratio.specular + r.ratio.diffuse;
//
// Conventions: world space; a convex polygon_light of at most 8 vertices; f the true GGX BRDF, not
// its LTC. Degenerate cases: 0 and no queries for ltc::shade's bad input, more than 8 vertices or
// a zero analytic part; exactly the analytic result where nothing occludes the light or K = 0.
#pragma once

#include <ltc/config.hpp>
#include <ltc/brdf/ggx.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/core/ltc_polygon_sampling.hpp>
#include <ltc/core/polygon_area_sampling.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>
#include <ltc/core/screen_order.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/shading/ggx_models.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/lobes.hpp>
#include <ltc/shading/polygon_light_integrals.hpp>
#include <ltc/shading/polygon_light_radiance.hpp>
#include <ltc/shading/shade.hpp>
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/surface.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

LTC_NAMESPACE_BEGIN

/// The techniques of shade_shadowed's samples: K in all (on average, with rejection), one
/// visibility query each (none for a sample below the surface, where both integrands vanish),
/// every sample serving both terms:
///   ltc_polygon  the specular share from the LTC restricted to the polygon, density D / I_D:
///                where the light holds at least options.rejection_from of the lobe, by
///                rejection: N = K_s / I_D draws of the whole LTC (Algorithm 1: no sampler to
///                build), those that hit the light kept (K_s on average, no query for the
///                others); elsewhere by the exact sampler (ltc/core/ltc_polygon_sampling.hpp).
///                The diffuse share from options.diffuse: light_area (the default: uniform on the
///                light) or cosine (the clamped cosine restricted to the polygon, exact, density
///                cos / E: ltc/core/projected_solid_angle_sampling.hpp; dearer per sample, for
///                constant diffuse weights where area samples' vary most: lights close to or
///                grazing the surface). K_s and K_d are in proportion to the LTC technique's and
///                the rest's shares of the analytic result (shade_shadowed), and every sample is
///                weighted by the balance heuristic over the whole plan (multi-sample MIS, Veach
///                1997 eq. 9.13: f / (K_s D / I_D + K_d p_d), or f / (N D + K_d p_d) with
///                rejection; the normalizers in closed form). Where the light is unoccluded the
///                ratio is exactly 1 (the analytic result, without noise); where the LTC takes all
///                the samples, f / p varies only by the GGX/LTC mismatch, so the ratio is close to
///                the visible fraction of the samples.
///   light_area   K points uniform on the light's area (ltc/core/polygon_area_sampling.hpp),
///                density |x - P|^2 / (A |cos theta_x|), for both terms: the common renderer
///                baseline.
/// f is the true BRDF, not its LTC: the GGX lobe without Fresnel (ltc/brdf/ggx.hpp,
/// alpha = roughness^2, the roughness clamped to [0, 1] as the tables read it) for the specular
/// term, cos / pi for the diffuse one; the ratio corrects the analytic result for visibility only
/// (a model fitted to another BRDF keeps GGX here).
enum class shadow_sampler { ltc_polygon, light_area };
/// The diffuse share's technique under shadow_sampler::ltc_polygon (shadow_sampler's comment).
enum class diffuse_sampler { light_area, cosine };

/// The sample plan of shade_shadowed (shadow_sampler's comment); the analytic part is the model's.
/// The directions are a rank-1 lattice, (k + 1/2) / n and k / phi (the golden ratio) modulo 1, n
/// the sampler's own count, shifted by `rotation` (Cranley-Patterson rotation: pass a random
/// shift per pixel to turn the structured error into noise). Where a renderer filters the
/// estimates over neighbouring pixels, the shifts can instead be stratified across pixels:
/// rotation = ltc::screen_point(x, y, image_seed) with stratified_rotation, which shifts each
/// technique's lattice of n points by rotation.x / n, one period of its first coordinate, so that
/// the n 4^k first coordinates of an aligned 2^k x 2^k block of pixels with the same n fall one
/// per interval of width 1 / (n 4^k) (a shift by rotation.x itself stratifies nothing but the
/// points' common offset; a shift by rotation.x / K, K the total count, would cover only part of
/// the periods of a technique whose n is not a multiple of K, and bias its sums). Each sum keeps
/// its expectation over a uniform rotation (the n intervals of width 1 / n that the first
/// coordinates sweep tile [0, 1)); the ratio, a nonlinear function of them, is not distributed
/// exactly as with random shifts (docs/design_notes.md, "Shadows: sampling the LTC over a
/// polygon", compares the two).
template <typename T>
struct shadow_sampling {
    std::size_t samples = 4;        ///< K: directions (visibility queries) per call
    /// Cranley-Patterson shift in [0, 1)^2, per pixel: random, or ltc::screen_point with stratified_rotation
    glm::vec<2, T> rotation{T(0)};
    /// Each technique's lattice of n points shifted by rotation.x / n along its first coordinate,
    /// which repeats every 1 / n, instead of by rotation.x: for rotations stratified across pixels
    /// (ltc::screen_point of ltc/core/screen_order.hpp), so that a block of pixels' lattices of one
    /// n are stratified together (the struct's comment). Either way each sum keeps its expectation for a
    /// uniform rotation.
    bool stratified_rotation = false;
    shadow_sampler sampler = shadow_sampler::ltc_polygon;
    diffuse_sampler diffuse = diffuse_sampler::light_area;
    T rejection_from{T(0.125)};     ///< I_D from which the LTC share is drawn by rejection (> 1: never)
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

/// The occluded samples' blockers, from a first-hit visibility callback (first_hit): over
/// the samples whose query met an occluder at t_b < t_l (t_l the light's plane's distance along
/// the ray), the sum of t_b / (t_l - t_b) and their number. Both are sums, so a renderer can
/// filter them over neighbouring pixels (weighted: `occluded` need not stay an integer) before
/// penumbra_width, as it filters ratio_estimates. 0 and 0 for a boolean callback.
template <typename T>
struct blocker_estimates {
    T ratio_sum{0};  ///< sum over the occluded samples of t_b / (t_l - t_b)
    T occluded{0};   ///< the occluded samples
};

/// A visibility callback that answers with the first occluder's distance (first_hit): what
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
/// along the ray (+inf where none) instead of a visibility: shade_shadowed then records the
/// occluded samples' blockers (blocker_estimates). The callback returns the distance t_b to the
/// first occluder along the direction (a floating-point value; `distance` or more, or +inf, where
/// nothing occludes): the sample is occluded where t_b < distance (a NaN is not; a negative t_b
/// counts as 0), and the result's `blockers` then sums t_b / (t_l - t_b) over the occluded
/// samples, t_l = distance: the estimate of a penumbra's width of percentage-closer soft shadows
/// (penumbra_width; Fernando, SIGGRAPH 2005), with which a renderer that filters the estimates
/// can narrow its filter where the penumbra is narrow. The wrapper makes the distance explicit: a
/// callback that returns a float visibility or transmittance stays a boolean one.
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

/// What shade_shadowed returns: `unshadowed` (= ltc::shade<Model>(s, light)), `ratio` (the
/// estimator of Heitz et al.: biased, consistent, exact when nothing occludes the light),
/// `unbiased` (plain Monte Carlo of the true BRDF, Schlick's Fresnel included, with the same
/// samples and visibility: sum f V / (sum_k n_k p_k), for comparison; it carries the BRDF's noise
/// instead of the LTC's fitting error), and per term the ratio's two sums (`specular_estimates`,
/// `diffuse_estimates`), for renderers that denoise the shadows as Heitz et al. do: filter each of
/// the two over neighbouring pixels, then ltc::ratio_shading, so that the filter blurs the
/// visibility only, never the analytic shading. Each term's estimates also carry the analytic
/// part's value of what `total` estimates (the sum over the model's lobes of magnitude times
/// integral; the form factor for the diffuse term), and `specular_fresnel_estimates` the same for
/// f (1 - V.H)^5, Schlick's (1 - F0) part (the lobes' Fresnel channels): with them,
/// ltc::corrected_specular corrects the LTC's fitting error as well as the shadows (the filtered
/// estimate of the shadowed integral relative to the analytic one, per part of Hill's Fresnel
/// split). K = 0 gives the analytic result.
template <typename T>
struct shadowed_polygon_light_result {
    polygon_light_result<T> unshadowed;  ///< analytic LTC, no visibility
    polygon_light_result<T> ratio;       ///< Heitz et al. 2018's ratio estimator
    polygon_light_result<T> unbiased;    ///< Monte Carlo of the true BRDF with the same samples
    std::size_t rays = 0;                ///< visibility queries made
    ratio_estimates<T> specular_estimates;  ///< the specular ratio's two sums and analytic value (for denoising)
    ratio_estimates<T> diffuse_estimates;   ///< the diffuse ratio's two sums and analytic value (for denoising)
    /// The specular sums with f (1 - V.H)^5, Schlick's (1 - F0) part, its analytic value the
    /// lobes' Fresnel channels times their integrals (for corrected_specular).
    ratio_estimates<T> specular_fresnel_estimates;
    /// The occluded samples' blocker distances, with a first-hit callback (first_hit).
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
/// `per_period` ((k + 1/2 + s_x) / K, k / phi + s_y) mod 1 (shadow_sampling::stratified_rotation).
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

/// polygon_light's light interface (the same integrals, so shade_lobes gives ltc::shade's bits),
/// which also keeps what the estimator needs of the integrals: those of the integrals() call
/// (the lobe the samples follow), signed (their magnitudes normalize the densities) and sided, and
/// the sided result of the last ltc_integral() call (a second lobe).
template <typename T>
class recording_polygon_light {
public:
    using vec3 = glm::vec<3, T>;
    explicit recording_polygon_light(const polygon_light<T>& light) : light_(light) {}

    template <typename Policy>
    polygon_light_integrals<T> integrals(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                                         const shade_options& o) const {
        // polygon_light::integrals, keeping the signed values.
        signed_ = integrate_polygon_light_at<Policy>(
            frame, m_inv, P, [this](std::size_t i) { return light_.vertex(i); }, light_.size(), o.clip);
        sided_.form_factor = apply_sidedness(signed_.form_factor, light_.sides());
        sided_.ltc = apply_sidedness(signed_.ltc, light_.sides());
        return sided_;
    }
    template <typename Policy>
    T ltc_integral(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                   const shade_options& o) const {
        further_ = light_.template ltc_integral<Policy>(frame, P, m_inv, o);
        return further_;
    }
    vec3 emitted(const vec3& scale, T integral) const { return light_.emitted(scale, integral); }

    const polygon_light_integrals<T>& signed_integrals() const { return signed_; }
    const polygon_light_integrals<T>& sided_integrals() const { return sided_; }
    T further_integral() const { return further_; }

private:
    const polygon_light<T>& light_;
    mutable polygon_light_integrals<T> signed_, sided_;
    mutable T further_{0};
};

/// The analytic part of shade_shadowed for one lobe set: ltc::shade's result and what the
/// estimator takes from it.
template <typename T>
struct shadowed_analytic {
    shading_result<T> unshadowed;
    ltc_coefficients<T> sampled;              ///< the LTC whose restriction to the light the specular share samples
    polygon_light_integrals<T> sampled_signed;  ///< its integral and the form factor, signed
    T f{0}, fresnel{0}, form_factor{0};       ///< analytic values of int f, int f (1 - V.H)^5, E (sided)
    T ltc_share{0};                           ///< the LTC technique's share of the analytic result (sum of channels)
};

template <typename T>
inline T channel_sum(const glm::vec<3, T>& c) {
    return c.x + c.y + c.z;
}

// One overload per lobe set (ltc/shading/lobes.hpp; shade_shadowed's comment: where the samples go).

template <typename Policy, typename T>
inline shadowed_analytic<T> shadowed_analytic_part(const shading_point<T>& p, const lobes::one<T>& c,
                                                   const recording_polygon_light<T>& light) {
    shadowed_analytic<T> a;
    a.unshadowed = shade_lobes<Policy>(p, c, light, shade_options{});
    const polygon_light_integrals<T>& I = light.sided_integrals();
    a.sampled = c.ltc;
    a.sampled_signed = light.signed_integrals();
    a.f = c.ltc.magnitude * I.ltc;
    a.fresnel = c.ltc.fresnel * I.ltc;
    a.form_factor = I.form_factor;
    a.ltc_share = channel_sum(a.unshadowed.specular);
    return a;
}

template <typename Policy, typename T>
inline shadowed_analytic<T> shadowed_analytic_part(const shading_point<T>& p, const lobes::ltc_and_cosine<T>& c,
                                                   const recording_polygon_light<T>& light) {
    shadowed_analytic<T> a;
    a.unshadowed = shade_lobes<Policy>(p, c, light, shade_options{});
    const polygon_light_integrals<T>& I = light.sided_integrals();
    a.sampled = c.ltc;
    a.sampled_signed = light.signed_integrals();
    // The cosine's integral is the form factor.
    a.f = c.ltc.magnitude * I.ltc;
    a.f += c.cosine.magnitude * I.form_factor;
    a.fresnel = c.ltc.fresnel * I.ltc;
    a.fresnel += c.cosine.fresnel * I.form_factor;
    a.form_factor = I.form_factor;
    // The LTC's part of the specular term (shade_lobes' first product): the cosine's goes to K_d.
    a.ltc_share = channel_sum(light.emitted(brdf_scale(p.f0, c.ltc), I.ltc));
    return a;
}

template <typename Policy, typename T>
inline shadowed_analytic<T> shadowed_analytic_part(const shading_point<T>& p, const lobes::two<T>& c,
                                                   const recording_polygon_light<T>& light) {
    shadowed_analytic<T> a;
    a.unshadowed = shade_lobes<Policy>(p, c, light, shade_options{});
    const polygon_light_integrals<T>& I = light.sided_integrals();
    const T second = light.further_integral();
    a.sampled = c.first;
    a.sampled_signed = light.signed_integrals();
    a.f = c.first.magnitude * I.ltc;
    a.f += c.second.magnitude * second;
    a.fresnel = c.first.fresnel * I.ltc;
    a.fresnel += c.second.fresnel * second;
    a.form_factor = I.form_factor;
    a.ltc_share = channel_sum(a.unshadowed.specular);
    return a;
}

}  // namespace detail

/// Shading of a constant-radiance polygonal light with visibility: ltc::shade<Model,
/// Policy>(s, light) as `unshadowed`, times the ratio estimator of Heitz et al. 2018 (eq. 4) over
/// options.samples visibility queries of `visible` (the samples: shadow_sampler, shadow_sampling;
/// the outputs: shadowed_polygon_light_result).
///
/// The analytic part. shade_shadowed<Model>(s, light, ...) shades the model's lobe set
/// (ltc/shading/lobes.hpp) as ltc::shade<Model>(s, light) does, with the same bits: `unshadowed`
/// is that result (horizon clipping ltc_space, the paper's order). The model decides the lobes and
/// with them where the LTC technique samples:
///   lobes::one             (ggx::one_lobe) the samples follow the LTC, for the whole specular term;
///   lobes::ltc_and_cosine  (ggx::ltc_and_cosine, the default) they follow the LTC for its part of
///                          the specular term only; the cosine's part joins the diffuse share
///                          (K_d), whose technique covers the broad part that the LTC, fitted next
///                          to the cosine, leaves out;
///   lobes::two             (ggx::two_lobes) they follow the first lobe (the estimator only needs
///                          a density), for the whole specular term, which the second lobe's
///                          integral brings closer to GGX.
///
/// The light: a polygon_light (ltc/shading/lights/polygon_light.hpp), a convex planar polygon of at
/// most 8 vertices, one-sided or two-sided; the samplers walk its vertices in the light's own
/// order (polygon_light::vertex), so a one-sided light gives the same bits whichever order its
/// caller's vertices come in. The other light shapes of ltc::shade have no shadowed form: their
/// samplers are the polygon's.
///
/// Visibility callback: bool visible(origin, unit direction, distance), all world space, the
/// distance to the light's plane along the direction; offset origin and distance by the
/// renderer's own epsilon; its answer is converted to bool. Or, from a closest-hit query,
/// ltc::first_hit(callback): the first occluder's distance, and the blockers (first_hit).
///
/// Zero results, no queries: where the analytic part is 0, a light that faces away from P
/// (one-sided: its integrals vanish, up to the rounding of ltc::shade's where it barely rises above
/// the horizon) or lies below the horizon; bad input, as ltc::shade: a position, normal or view
/// vector not finite, a zero normal or view; a polygon of fewer than 3 or more than 8 vertices (the
/// samplers' fixed storage: no allocation).
template <typename Model = ggx::ltc_and_cosine, typename Policy = edge_policy::automatic, typename T,
          typename Visible>
shadowed_polygon_light_result<T> shade_shadowed(const surface<T>& s, const polygon_light<T>& light, Visible&& visible,
                                                const shadow_sampling<T>& options = {}) {
    using vec3 = glm::vec<3, T>;
    static_assert(!detail::takes_tangent<Model, T>::value,
                  "shade_shadowed: isotropic models only (its sampled part evaluates isotropic GGX)");
    constexpr std::size_t max_vertices = 8;
    shadowed_polygon_light_result<T> r;
    const std::size_t n = light.size();
    // ltc::shade's bad input (a zero normal: the frame's test below), and the samplers' storage.
    if (!detail::finite(s.position) || !detail::finite(s.normal) || !detail::finite(s.view) ||
        s.view == vec3(T(0)) || n < 3 || n > max_vertices)
        return r;
    const shading_point<T> p = make_shading_point(s);
    const shading_frame<T>& frame = p.frame;
    if (!frame.valid) return r;
    const vec3 &P = s.position, &F0 = s.f0, &albedo = s.albedo, &radiance = light.radiance();
    // The analytic part: shade_lobes of the model's lobe set, as ltc::shade (the model's table
    // clamps the roughness itself).
    const detail::recording_polygon_light<T> recorder(light);
    const detail::shadowed_analytic<T> a =
        detail::shadowed_analytic_part<Policy>(p, Model::template fetch<T>(frame.cos_theta_v, s.roughness), recorder);
    r.unshadowed = a.unshadowed;
    const polygon_light_integrals<T>& I = a.sampled_signed;
    const T analytic_f = a.f, analytic_fresnel = a.fresnel, form_factor = a.form_factor;
    r.specular_estimates.analytic = analytic_f;
    r.specular_fresnel_estimates.analytic = analytic_fresnel;
    r.diffuse_estimates.analytic = form_factor;
    r.ratio = r.unshadowed;
    const T weight_s = r.unshadowed.specular.x + r.unshadowed.specular.y + r.unshadowed.specular.z;
    const T weight_d = r.unshadowed.diffuse.x + r.unshadowed.diffuse.y + r.unshadowed.diffuse.z;
    const T weight_ltc = a.ltc_share;  // the LTC technique's share (shadow_sampler's comment)
    const std::size_t K = options.samples;
    if (!(weight_s + weight_d > T(0)) || K == 0) return r;

    // The light's vertices in its own order (one-sided: its front turns clockwise).
    vec3 vertices[max_vertices], local[max_vertices];
    for (std::size_t i = 0; i < n; ++i) vertices[i] = light.vertex(i);
    for (std::size_t i = 0; i < n; ++i) local[i] = frame.to_local(vertices[i] - P);
    const polygon_area_sampler<T, max_vertices> plane(vertices, n);
    const vec3 v_local(detail::safe_sqrt(T(1) - frame.cos_theta_v * frame.cos_theta_v), T(0), frame.cos_theta_v);
    const T roughness = detail::saturate(s.roughness);  // as the tables read it
    const T alpha = roughness * roughness;
    const auto d = transformed<clamped_cosine<T>>::from_inverse(a.sampled.m_inv);
    const T i_d = std::abs(I.ltc), e = pi<T>() * std::abs(I.form_factor);  // the two densities' normalizers

    // The callback's answer: visible, or with ltc::first_hit the first occluder's distance
    // (first_hit), which adds its PCSS ratio to the blockers where the sample is occluded.
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
        // Where the light holds at least rejection_from of the lobe, the restricted LTC by rejection:
        // draws of the whole LTC (Algorithm 1), those that hit the light kept (no query for the others).
        const bool reject = ks > 0 && i_d >= options.rejection_from && i_d > T(0);
        // At most 8 K_s draws, capped before the conversion: K_s / I_D overflows an integer
        // where I_D is tiny (options.rejection_from = 0).
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
            T q = T(draws) * lobe;
            if (kd > 0) q += T(kd) * (cosine ? glm::max(l.z, T(0)) / e : plane.solid_angle_pdf(P, P + w * t));
            return q;
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
