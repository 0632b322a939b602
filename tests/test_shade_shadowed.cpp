// ltc::shade_shadowed<Model> (ltc/shading/shade_shadowed.hpp): the shadowed shading with the
// material model as a type, and its deprecated names (ltc/shading/shadowed_polygon_light.hpp).
//   (a) nothing occludes: `unshadowed` is ltc::shade<Model, Policy>(s, light) bit for bit, for each
//       model, two edge policies, lights one-sided by emission normal or by winding and
//       two-sided, random scenes and sample plans; the ratio is then the analytic shading bit for
//       bit, each query is counted, each term's two sums are equal, and the estimates' analytic
//       values make up the analytic shading (Hill's split: a few float roundings of positive
//       terms, 1e-6 relative in float, 1e-14 in double, for one lobe or two);
//   (b) a one-sided light built with an emission normal gives the same bits from either order of
//       its vertices, and so do the two winding conventions of one polygon in its two orders,
//       under random occluders and sample plans; from behind (the emission normal away from P)
//       it gives 0 and makes no query;
//   (c) bad input as ltc::shade's (a non-finite position, normal or view, a zero normal or view),
//       and polygons of 2 or 9 vertices: 0 and no query;
//   (d) the deprecated shade_polygon_light_shadowed against its implementation before
//       shade_shadowed (`before`, below, verbatim): every output bit for bit, over random scenes,
//       sidednesses, sample plans and occluders (boolean and first-hit callbacks) with fixed
//       seeds, for each analytic_lobes value, in float and double;
//   (e) each model against closed forms and the library's Monte Carlo ground truth, with a
//       half-space occluder through the shading point (as tests/test_shadowed_polygon_light.cpp
//       for the deprecated name): the diffuse ratio against E(visible) / E(light), the specular
//       ratio against int_vis f / int_light f (f the GGX lobe), the unbiased estimate against
//       int_vis f (F0 = 1), and each term's two sums against the integrals they estimate, for four
//       sample plans. Tolerance: 4 standard errors of the mean over R = 16 independent
//       Cranley-Patterson shifts at K = 1024 (sigma from the spread of the R results) combined
//       with the ground truth's, plus 1e-4 relative for float rounding of 1024-term sums. The ratio
//       estimator's O(1/K) bias (about CV^2 / K relative, CV the coefficient of variation of
//       f / p) is CV sqrt(R / K) standard errors of the mean: at most 0.4 for CV <= 3.
#include "support/rng.hpp"

#include <ltc/brdf/ggx.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/ggx_models.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/shade.hpp>
#include <ltc/shading/shade_shadowed.hpp>
#include <ltc/shading/shadowed_polygon_light.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace ltc_test_shade_shadowed {  // the file's own names, apart from the other files of a unity batch

// shade_polygon_light_shadowed as it was before ltc::shade_shadowed (commit a8f79a0), verbatim but
// for this namespace, kept as the reference of the deprecated wrapper's bits (d).
namespace before {
using namespace ltc;

namespace detail {
using namespace ltc::detail;  // safe_sqrt, safe_normalize, is_first_hit

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

}  // namespace before

namespace {

template <typename T>
using vec3 = glm::vec<3, T>;

// Bit for bit (memcmp: +0 and -0 differ, and so would two NaNs of different payloads).
template <typename T>
bool same(T a, T b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}
template <typename T>
bool same(const vec3<T>& a, const vec3<T>& b) {
    return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}
template <typename T>
bool same(const ltc::shading_result<T>& a, const ltc::shading_result<T>& b) {
    return same(a.specular, b.specular) && same(a.diffuse, b.diffuse);
}
template <typename T>
bool same(const ltc::ratio_estimates<T>& a, const ltc::ratio_estimates<T>& b) {
    return same(a.visible, b.visible) && same(a.total, b.total) && same(a.analytic, b.analytic);
}
template <typename T>
bool same(const ltc::shadowed_polygon_light_result<T>& a, const ltc::shadowed_polygon_light_result<T>& b) {
    return same(a.unshadowed, b.unshadowed) && same(a.ratio, b.ratio) && same(a.unbiased, b.unbiased) &&
           a.rays == b.rays && same(a.specular_estimates, b.specular_estimates) &&
           same(a.diffuse_estimates, b.diffuse_estimates) &&
           same(a.specular_fresnel_estimates, b.specular_fresnel_estimates) &&
           same(a.blockers.ratio_sum, b.blockers.ratio_sum) && same(a.blockers.occluded, b.blockers.occluded);
}

/// A random shading point and convex planar light, sample plan and half-space occluder.
template <typename T>
struct random_case {
    ltc::surface<T> s;
    vec3<T> radiance{T(1)};
    std::vector<vec3<T>> vertices;  ///< 3..8, in either orientation
    glm::dvec3 centre{0.0}, axis{0.0};  ///< the polygon's centre and the unit normal of its plane
    ltc::sidedness side = ltc::sidedness::one_sided;
    ltc::shadow_options<T> options;  ///< lobes: set by the test
    vec3<T> occluder{T(0)};          ///< visible where d . occluder >= offset
    T offset{0}, hit_fraction{0};    ///< and with a first-hit callback, an occluder at hit_fraction of the distance
};

template <typename T>
random_case<T> make_case(ltc_test::rng& g) {
    // One draw per statement: the order of evaluation of arguments is unspecified.
    const auto v3 = [&](double lo, double hi) {
        const T x = T(g.uniform(lo, hi));
        const T y = T(g.uniform(lo, hi));
        const T z = T(g.uniform(lo, hi));
        return vec3<T>(x, y, z);
    };
    random_case<T> c;
    c.s.position = v3(-2, 2);
    const glm::dvec3 n = g.direction();
    c.s.normal = vec3<T>(n * g.uniform(0.5, 2.0));  // any length
    glm::dvec3 v = g.direction();
    if (glm::dot(v, n) < 0 && g.uniform() < 0.9) v = -v;  // mostly above the surface
    c.s.view = vec3<T>(v * g.uniform(0.5, 2.0));
    const double u = g.uniform();
    c.s.roughness = u < 0.05 ? T(0) : u < 0.1 ? T(1) : T(g.uniform());
    c.s.f0 = v3(0, 1);
    c.s.albedo = v3(0, 1);
    c.radiance = v3(0.1, 4);
    // The light around a centre mostly above the surface, its plane at any angle: points of an
    // ellipse in the order of their angles (convex), the order then reversed half the time.
    glm::dvec3 towards = g.direction();
    if (glm::dot(towards, n) < 0 && g.uniform() < 0.8) towards = -towards;
    const double distance = g.uniform(0.3, 4.0);
    c.centre = glm::dvec3(c.s.position) + distance * towards;
    c.axis = g.direction();
    const glm::dvec3 a =
        glm::normalize(glm::cross(c.axis, std::abs(c.axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 b = glm::cross(c.axis, a);
    const double ra = distance * g.uniform(0.05, 1.0), rb = distance * g.uniform(0.05, 1.0);
    std::vector<double> angles(3 + std::size_t(g.uniform() * 6));
    for (double& t : angles) t = 2 * 3.141592653589793 * g.uniform();
    std::sort(angles.begin(), angles.end());
    for (const double t : angles) c.vertices.push_back(vec3<T>(c.centre + ra * std::cos(t) * a + rb * std::sin(t) * b));
    if (g.uniform() < 0.5) std::reverse(c.vertices.begin(), c.vertices.end());
    c.side = g.uniform() < 0.7 ? ltc::sidedness::one_sided : ltc::sidedness::two_sided;
    constexpr std::size_t counts[] = {0, 1, 2, 3, 4, 5, 8, 13, 16, 32};
    c.options.samples = counts[std::size_t(g.uniform() * 10)];
    c.options.rotation = g.uniform2<T>();
    c.options.stratified_rotation = g.uniform() < 0.5;
    c.options.sampler = g.uniform() < 0.8 ? ltc::shadow_sampler::ltc_polygon : ltc::shadow_sampler::light_area;
    c.options.diffuse = g.uniform() < 0.5 ? ltc::diffuse_sampler::cosine : ltc::diffuse_sampler::light_area;
    const double r = g.uniform();
    c.options.rejection_from = r < 0.25 ? T(0) : r < 0.5 ? T(0.125) : r < 0.75 ? T(g.uniform()) : T(2);
    c.occluder = vec3<T>(g.direction());
    c.offset = T(g.uniform(-0.6, 0.6));
    c.hit_fraction = T(g.uniform(0.01, 0.99));
    return c;
}

/// Visible where d . m >= offset (a pure function of the direction), counting its queries.
template <typename T>
struct half_space {
    vec3<T> m;
    T offset;
    std::size_t* calls;
    bool operator()(const vec3<T>&, const vec3<T>& d, T) const {
        ++*calls;
        return glm::dot(d, m) >= offset;
    }
};

/// The same occluder answering with a first hit at `fraction` of the distance (+inf: none).
template <typename T>
struct half_space_hit {
    vec3<T> m;
    T offset, fraction;
    std::size_t* calls;
    T operator()(const vec3<T>&, const vec3<T>& d, T distance) const {
        ++*calls;
        return glm::dot(d, m) >= offset ? std::numeric_limits<T>::infinity() : distance * fraction;
    }
};

/// The case's light one-sided towards `emission` (its vertices in the caller's order).
template <typename T>
ltc::polygon_light<T> towards(const random_case<T>& c, const std::vector<vec3<T>>& v, const glm::dvec3& emission) {
    return ltc::polygon_light<T>::one_sided(v.data(), v.size(), vec3<T>(emission), c.radiance);
}

/// (a) for one model and policy: nothing occludes.
template <typename Model, typename Policy, typename T>
void check_unoccluded(const random_case<T>& c, const ltc::polygon_light<T>& light, std::size_t& shaded) {
    std::size_t calls = 0;
    const auto always = [&](const vec3<T>&, const vec3<T>&, T) { return ++calls > 0; };
    const ltc::shadow_sampling<T>& o = c.options;  // the plan alone: the model decides the lobes
    const auto r = ltc::shade_shadowed<Model, Policy>(c.s, light, always, o);
    const ltc::shading_result<T> want = ltc::shade<Model, Policy>(c.s, light);
    CHECK(same(r.unshadowed, want));
    CHECK(same(r.ratio, r.unshadowed));
    CHECK(r.rays == calls);
    CHECK(r.rays <= 8 * c.options.samples);
    CHECK(same(r.specular_estimates.visible, r.specular_estimates.total));
    CHECK(same(r.specular_fresnel_estimates.visible, r.specular_fresnel_estimates.total));
    CHECK(same(r.diffuse_estimates.visible, r.diffuse_estimates.total));
    // The analytic values: the diffuse term's bit for bit (shade_lobes' product), the specular
    // term's by Hill's split; every coefficient and integral is >= 0, so the few roundings on
    // either side (fewer than 8 per channel each) stay within 16 eps relative.
    CHECK(same(r.unshadowed.diffuse, light.emitted(c.s.albedo, r.diffuse_estimates.analytic)));
    const vec3<T> split = c.radiance * (c.s.f0 * r.specular_estimates.analytic +
                                        (vec3<T>(T(1)) - c.s.f0) * r.specular_fresnel_estimates.analytic);
    const T eps = std::numeric_limits<T>::epsilon();
    for (int k = 0; k < 3; ++k) CHECK(std::abs(split[k] - want.specular[k]) <= 16 * eps * want.specular[k]);
    if (want.specular.x + want.diffuse.x > T(0)) ++shaded;
}

template <typename Model, typename T>
void check_unoccluded_all(const random_case<T>& c, std::size_t& shaded) {
    const std::vector<vec3<T>>& v = c.vertices;
    const ltc::polygon_light<T> lights[] = {
        towards(c, v, c.axis),
        towards(c, v, -c.axis),
        ltc::polygon_light<T>::one_sided(v.data(), v.size(), ltc::winding::counter_clockwise_front, c.radiance),
        ltc::polygon_light<T>::one_sided(v.data(), v.size(), ltc::winding::clockwise_front, c.radiance),
        ltc::polygon_light<T>::two_sided(v.data(), v.size(), c.radiance)};
    for (const auto& light : lights) {
        check_unoccluded<Model, ltc::edge_policy::automatic>(c, light, shaded);
        check_unoccluded<Model, ltc::edge_policy::exact>(c, light, shaded);
    }
}

/// Every output 0 and no query.
template <typename T>
bool nothing(const ltc::shadowed_polygon_light_result<T>& r, std::size_t calls) {
    return same(r, ltc::shadowed_polygon_light_result<T>{}) && calls == 0;
}

}  // namespace

TEMPLATE_TEST_CASE("shade_shadowed: unoccluded, the analytic part is ltc::shade<Model> bit for bit", "[shadows]", float,
                   double) {
    using T = TestType;
    ltc_test::rng g(37001);
    std::size_t shaded = 0, calls = 0;
    for (int i = 0; i < 400; ++i) {
        const random_case<T> c = make_case<T>(g);
        CAPTURE(i);
        check_unoccluded_all<ltc::ggx::one_lobe>(c, shaded);
        check_unoccluded_all<ltc::ggx::ltc_and_cosine>(c, shaded);
        check_unoccluded_all<ltc::ggx::two_lobes>(c, shaded);
        calls += 30;
    }
    // The random scenes shade most lights: a light of the pair of facings always faces P.
    CHECK(shaded > calls / 3);
}

TEMPLATE_TEST_CASE("shade_shadowed: the same bits from either vertex order, 0 from behind", "[shadows]", float,
                   double) {
    using T = TestType;
    ltc_test::rng g(37002);
    std::size_t lit = 0, cases = 0, behind_cases = 0, exactly_zero = 0;
    const auto check = [&](const auto model, const random_case<T>& c) {
        using Model = decltype(model);
        std::vector<vec3<T>> reversed(c.vertices.rbegin(), c.vertices.rend());
        const auto run = [&](const ltc::polygon_light<T>& light, bool first_hit, std::size_t& calls) {
            const ltc::shadow_sampling<T>& o = c.options;
            return first_hit ? ltc::shade_shadowed<Model>(
                                   c.s, light, ltc::first_hit(half_space_hit<T>{c.occluder, c.offset, c.hit_fraction, &calls}), o)
                             : ltc::shade_shadowed<Model>(c.s, light, half_space<T>{c.occluder, c.offset, &calls}, o);
        };
        for (const bool first_hit : {false, true}) {
            CAPTURE(first_hit);
            for (const double sign : {1.0, -1.0}) {
                std::size_t calls_a = 0, calls_b = 0;
                const auto a = run(towards(c, c.vertices, sign * c.axis), first_hit, calls_a);
                const auto b = run(towards(c, reversed, sign * c.axis), first_hit, calls_b);
                CHECK(same(a, b));
                CHECK(calls_a == calls_b);
                // From behind (P on the other side of the light's plane than its emission normal):
                // ltc::shade's 0, and then no query. The signed integrals are then <= 0, so the
                // sided ones 0, up to the rounding of a vanishing one (a light that barely rises
                // above the horizon): (1 / 2 pi) times n edge terms of at most pi each, ~10
                // roundings apiece with the clip, summed with n more, times the lobes' scale (the
                // tables' F0 magnitude + (1 - F0) fresnel summed over the lobes stays below 2)
                // and the radiance: (10 + n) n eps radiance, (16 + n) n eps radiance with margin.
                const bool behind = sign * glm::dot(glm::dvec3(c.s.position) - c.centre, c.axis) < 0;
                if (behind) {
                    const ltc::shading_result<T> want = ltc::shade<Model>(c.s, towards(c, c.vertices, sign * c.axis));
                    const T n = T(c.vertices.size()), eps = std::numeric_limits<T>::epsilon();
                    for (int k = 0; k < 3; ++k) {
                        CHECK(want.specular[k] <= (16 + n) * n * eps * c.radiance[k]);
                        CHECK(want.diffuse[k] <= (16 + n) * n * eps * c.radiance[k]);
                    }
                    if (same(want, ltc::shading_result<T>{})) {
                        CHECK(nothing(a, calls_a));
                        ++exactly_zero;
                    }
                    ++behind_cases;
                }
                if (!behind && a.unshadowed.specular.x + a.unshadowed.diffuse.x > T(0)) ++lit;
                ++cases;
            }
            // The two winding conventions name the two orders of one face.
            std::size_t calls_a = 0, calls_b = 0;
            const auto ccw = ltc::polygon_light<T>::one_sided(c.vertices.data(), c.vertices.size(),
                                                              ltc::winding::counter_clockwise_front, c.radiance);
            const auto cw = ltc::polygon_light<T>::one_sided(reversed.data(), reversed.size(),
                                                             ltc::winding::clockwise_front, c.radiance);
            const auto a = run(ccw, first_hit, calls_a);
            CHECK(same(a, run(cw, first_hit, calls_b)));
            CHECK(calls_a == calls_b);
        }
    };
    for (int i = 0; i < 400; ++i) {
        const random_case<T> c = make_case<T>(g);
        CAPTURE(i);
        check(ltc::ggx::one_lobe{}, c);
        check(ltc::ggx::ltc_and_cosine{}, c);
        check(ltc::ggx::two_lobes{}, c);
    }
    CHECK(lit > cases / 4);  // half the cases face away
    // One facing of each pair is from behind; there the result is exactly 0 but for the rare
    // vanishing integrals.
    CHECK(behind_cases == cases / 2);
    CHECK(exactly_zero >= behind_cases * 9 / 10);
}

TEMPLATE_TEST_CASE("shade_shadowed: bad input gives 0 and no query", "[shadows]", float, double) {
    using T = TestType;
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
    const vec3<T> quad[4] = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}};
    const auto light = ltc::polygon_light<T>::one_sided(quad, 4, vec3<T>(0, 0, -1), vec3<T>(1));
    const ltc::surface<T> good{vec3<T>(0), vec3<T>(0, 0, 1), vec3<T>(0.3, 0, 1), T(0.4), vec3<T>(0.04), vec3<T>(0.5)};
    ltc::shadow_sampling<T> o;
    o.samples = 8;
    std::size_t calls = 0;
    const auto count = [&](const vec3<T>&, const vec3<T>&, T) { return ++calls > 0; };
    const auto check = [&](const auto model) {
        using Model = decltype(model);
        calls = 0;
        REQUIRE(ltc::shade_shadowed<Model>(good, light, count, o).rays > 0);  // the reference case shades
        std::vector<ltc::surface<T>> bad;
        for (const vec3<T> x : {vec3<T>(nan, 0, 0), vec3<T>(0, inf, 0), vec3<T>(0, 0, -inf)}) {
            for (int field = 0; field < 3; ++field) {
                ltc::surface<T> s = good;
                (field == 0 ? s.position : field == 1 ? s.normal : s.view) = x;
                bad.push_back(s);
            }
        }
        ltc::surface<T> s = good;
        s.normal = vec3<T>(0);
        bad.push_back(s);
        s = good;
        s.view = vec3<T>(0);
        bad.push_back(s);
        for (std::size_t i = 0; i < bad.size(); ++i) {
            CAPTURE(i);
            calls = 0;
            CHECK(nothing(ltc::shade_shadowed<Model>(bad[i], light, count, o), calls));
            CHECK(ltc::shade<Model>(bad[i], light).specular == vec3<T>(0));  // the convention of ltc::shade
        }
        // Fewer than 3 vertices, or more than the samplers hold.
        const std::vector<vec3<T>> nine(9, quad[0]);
        for (const auto& l : {ltc::polygon_light<T>::two_sided(quad, 2, vec3<T>(1)),
                              ltc::polygon_light<T>::two_sided(nine.data(), 9, vec3<T>(1))}) {
            calls = 0;
            CHECK(nothing(ltc::shade_shadowed<Model>(good, l, count, o), calls));
        }
    };
    check(ltc::ggx::one_lobe{});
    check(ltc::ggx::ltc_and_cosine{});
    check(ltc::ggx::two_lobes{});
}

TEMPLATE_TEST_CASE("shade_shadowed: the deprecated shade_polygon_light_shadowed keeps its bits", "[shadows]", float,
                   double) {
    using T = TestType;
    ltc_test::rng g(37003);
    std::size_t cases = 0, shaded = 0, sampled = 0;
    for (int i = 0; i < 1000; ++i) {
        const random_case<T> c = make_case<T>(g);
        for (const auto lobes : {ltc::analytic_lobes::one, ltc::analytic_lobes::two, ltc::analytic_lobes::cosine_lobe}) {
            CAPTURE(i, static_cast<int>(lobes));
            ltc::shadow_options<T> o = c.options;
            o.lobes = lobes;
            const auto old_shade = [&](const auto& visible) {
                return before::shade_polygon_light_shadowed(c.s.position, c.s.normal, c.s.view, c.s.roughness, c.s.f0,
                                                            c.s.albedo, c.radiance, c.vertices.data(),
                                                            c.vertices.size(), c.side, visible, o);
            };
            const auto new_shade = [&](const auto& visible) {
                return ltc::shade_polygon_light_shadowed(c.s.position, c.s.normal, c.s.view, c.s.roughness, c.s.f0,
                                                         c.s.albedo, c.radiance, c.vertices.data(), c.vertices.size(),
                                                         c.side, visible, o);
            };
            std::size_t calls_old = 0, calls_new = 0;
            const auto a = old_shade(half_space<T>{c.occluder, c.offset, &calls_old});
            const auto b = new_shade(half_space<T>{c.occluder, c.offset, &calls_new});
            CHECK(same(a, b));
            CHECK(calls_old == calls_new);
            calls_old = calls_new = 0;
            const auto a_hit = old_shade(ltc::first_hit(half_space_hit<T>{c.occluder, c.offset, c.hit_fraction, &calls_old}));
            const auto b_hit = new_shade(ltc::first_hit(half_space_hit<T>{c.occluder, c.offset, c.hit_fraction, &calls_new}));
            CHECK(same(a_hit, b_hit));
            CHECK(calls_old == calls_new);
            ++cases;
            if (a.unshadowed.specular.x + a.unshadowed.diffuse.x > T(0)) ++shaded;
            if (a.rays > 0 && a.ratio.specular != a.unshadowed.specular) ++sampled;
        }
    }
    // Most random cases shade the light, and many of those are partly occluded.
    CHECK(shaded > cases / 3);
    CHECK(sampled > cases / 5);
}

namespace {

struct scene {
    glm::vec3 P{0.0f}, N{0, 0, 1}, V;
    float roughness;
    glm::vec3 light[4];
};

// tests/test_shadowed_polygon_light.cpp's scene: a 2 x 1.6 quad 2 units ahead, tilted towards
// the point; its vertices turn clockwise seen from P.
scene make_scene(float view_deg, float roughness) {
    scene s;
    const float t = glm::radians(view_deg);
    s.V = glm::vec3(0, -std::sin(t), std::cos(t));
    s.roughness = roughness;
    const glm::vec3 c(0.2f, 2.0f, 1.0f), ax(1, 0, 0), ay = glm::normalize(glm::vec3(0, 0.3f, 1));
    s.light[0] = c - ax - 0.8f * ay;
    s.light[1] = c - ax + 0.8f * ay;
    s.light[2] = c + ax + 0.8f * ay;
    s.light[3] = c + ax - 0.8f * ay;
    return s;
}

/// The GGX lobe times (1 - V.H)^5, Schlick's (1 - F0) part, for the ground truth (sampled as GGX).
template <typename T>
struct ggx_schlick_part {
    using vec3 = glm::vec<3, T>;
    static T eval(const vec3& V, const vec3& L, T alpha) {
        const vec3 h = glm::normalize(V + L);
        const T m = T(1) - glm::clamp(glm::dot(V, h), T(0), T(1));
        return ltc::brdf::ggx<T>::eval(V, L, alpha) * (m * m * m * m * m);
    }
    static T pdf(const vec3& V, const vec3& L, T alpha) { return ltc::brdf::ggx<T>::pdf(V, L, alpha); }
    static vec3 sample(const vec3& V, const glm::vec<2, T>& u, T alpha) {
        return ltc::brdf::ggx<T>::sample(V, u, alpha);
    }
};

/// The polygon clipped to the half-space x . m >= 0 (Sutherland-Hodgman), in double.
std::vector<glm::dvec3> clip_half_space(const std::vector<glm::dvec3>& p, const glm::dvec3& m) {
    std::vector<glm::dvec3> out;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::dvec3 a = p[i], b = p[(i + 1) % p.size()];
        const double da = glm::dot(a, m), db = glm::dot(b, m);
        if (da >= 0) out.push_back(a);
        if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

struct mean_and_error {
    double mean = 0, error = 0;
};

/// The mean and its standard error over R independent Cranley-Patterson shifts of each of the N
/// values that one call of `values(shift)` returns.
template <std::size_t N, typename F>
std::array<mean_and_error, N> over_shifts(int R, F&& values) {
    ltc_test::rng g(99);
    std::vector<std::array<double, N>> x;
    for (int r = 0; r < R; ++r) x.push_back(values(g.uniform2<float>()));
    std::array<mean_and_error, N> m;
    for (std::size_t c = 0; c < N; ++c) {
        for (const auto& v : x) m[c].mean += v[c] / R;
        double var = 0;
        for (const auto& v : x) var += (v[c] - m[c].mean) * (v[c] - m[c].mean) / (R - 1);
        m[c].error = std::sqrt(var / R);
    }
    return m;
}

/// Closed forms and ground truth of the scene's light and its part visible past the half-space
/// occluder d . m >= 0, in the shading frame (N = z, V in the xz-plane); the same for every
/// model, so computed once per scene.
struct reference {
    double e_all = 0, e_vis = 0, truth_ratio = 0, truth_ratio_error = 0;
    ltc::ground_truth::estimate all, vis, all_f, vis_f;
};

reference compute_reference(const scene& s, const glm::dvec3& m) {
    reference t;
    const ltc::shading_frame<double> f = ltc::make_shading_frame(glm::dvec3(s.N), glm::dvec3(s.V));
    std::vector<glm::dvec3> all;
    for (const glm::vec3& p : s.light) all.push_back(f.to_local(glm::dvec3(p) - glm::dvec3(s.P)));
    const std::vector<glm::dvec3> vis = clip_half_space(all, f.to_local(m));
    REQUIRE(vis.size() >= 3);
    t.e_all = ltc::form_factor(all.data(), all.size(), ltc::sidedness::two_sided);
    t.e_vis = ltc::form_factor(vis.data(), vis.size(), ltc::sidedness::two_sided);
    const glm::dvec3 V(std::sqrt(1 - f.cos_theta_v * f.cos_theta_v), 0, f.cos_theta_v);
    ltc::ground_truth::options opt;
    opt.samples = 1u << 20;
    const double alpha = double(s.roughness) * s.roughness;
    t.all = ltc::ground_truth::integrate(ltc::brdf::ggx<double>{}, V, alpha, all.data(), all.size(), opt);
    t.vis = ltc::ground_truth::integrate(ltc::brdf::ggx<double>{}, V, alpha, vis.data(), vis.size(), opt);
    const ggx_schlick_part<double> schlick;
    t.all_f = ltc::ground_truth::integrate(schlick, V, alpha, all.data(), all.size(), opt);
    t.vis_f = ltc::ground_truth::integrate(schlick, V, alpha, vis.data(), vis.size(), opt);
    t.truth_ratio = t.vis.mean / t.all.mean;
    t.truth_ratio_error =
        t.truth_ratio * std::hypot(t.vis.standard_error / t.vis.mean, t.all.standard_error / t.all.mean);
    return t;
}

/// compute_reference, once per (view, roughness).
const reference& reference_for(const scene& s, const glm::dvec3& m) {
    static std::map<std::pair<float, float>, reference> cache;
    const std::pair<float, float> key(s.V.y, s.roughness);
    auto it = cache.find(key);
    if (it == cache.end()) it = cache.emplace(key, compute_reference(s, m)).first;
    return it->second;
}

/// Four sample plans: 0 the default, 1 the LTC share from the exact sampler, 2 the diffuse share
/// from the exact cosine sampler (the LTC share by rejection), 3 light-area samples only.
ltc::shadow_sampling<float> plan(int which) {
    ltc::shadow_sampling<float> o;
    if (which == 1) o.rejection_from = 2.0f;
    if (which == 2) o.diffuse = ltc::diffuse_sampler::cosine, o.rejection_from = 0.0f;
    if (which == 3) o.sampler = ltc::shadow_sampler::light_area;
    return o;
}

}  // namespace

TEMPLATE_TEST_CASE("shade_shadowed: each model against closed forms and ground truth", "[shadows]",
                   ltc::ggx::one_lobe, ltc::ggx::ltc_and_cosine, ltc::ggx::two_lobes) {
    using Model = TestType;
    const auto [view, roughness] = GENERATE(table<float, float>({{20, 0.25f}, {60, 0.5f}}));
    const scene s = make_scene(view, roughness);
    const glm::vec3 radiance(2.0f), albedo(0.5f);
    const auto light = ltc::polygon_light<float>::one_sided(s.light, 4, s.P - s.light[0], radiance);  // towards P
    const ltc::surface<float> surface{s.P, s.N, s.V, s.roughness, glm::vec3(1.0f), albedo};  // F0 = 1: Schlick's factor 1
    const glm::dvec3 m = glm::normalize(glm::dvec3(1.0, 0.15, 0.1));  // cuts the light
    const auto visible = [&](const glm::vec3&, const glm::vec3& d, float) { return glm::dot(glm::dvec3(d), m) >= 0; };

    const reference& t = reference_for(s, m);
    const double e_all = t.e_all, e_vis = t.e_vis, truth_ratio = t.truth_ratio, truth_ratio_error = t.truth_ratio_error;
    const ltc::ground_truth::estimate &t_all = t.all, &t_vis = t.vis, &t_all_f = t.all_f, &t_vis_f = t.vis_f;
    REQUIRE(truth_ratio > 0.1);
    REQUIRE(truth_ratio < 0.9);

    for (int which = 0; which < 4; ++which) {
        CAPTURE(view, roughness, which, e_vis / e_all, truth_ratio);
        const int R = 16;
        ltc::shadow_sampling<float> o = plan(which);
        o.samples = 1024;
        const auto stats = over_shifts<9>(R, [&](const glm::vec2& shift) {
            o.rotation = shift;
            const auto r = ltc::shade_shadowed<Model>(surface, light, visible, o);
            const auto again = ltc::ratio_shading(r.unshadowed, r.specular_estimates, r.diffuse_estimates);
            CHECK(same(r.ratio, again));
            return std::array<double, 9>{double(r.ratio.diffuse.x) / r.unshadowed.diffuse.x,
                                         double(r.ratio.specular.x) / r.unshadowed.specular.x,
                                         double(r.unbiased.specular.x),
                                         r.diffuse_estimates.visible,
                                         r.diffuse_estimates.total,
                                         r.specular_estimates.visible,
                                         r.specular_estimates.total,
                                         r.specular_fresnel_estimates.visible,
                                         r.specular_fresnel_estimates.total};
        });
        const mean_and_error &diffuse = stats[0], &specular = stats[1], &unbiased = stats[2];
        CAPTURE(diffuse.mean, diffuse.error, specular.mean, specular.error, unbiased.mean, unbiased.error);
        CHECK(std::abs(diffuse.mean - e_vis / e_all) <= 4 * diffuse.error + 1e-4);
        CHECK(std::abs(specular.mean - truth_ratio) <= 4 * std::hypot(specular.error, truth_ratio_error) + 1e-4);
        const double want = radiance.x * t_vis.mean;
        CHECK(std::abs(unbiased.mean - want) <= 4 * std::hypot(unbiased.error, radiance.x * t_vis.standard_error) + 1e-4 * want);
        const auto within = [](const mean_and_error& x, double target, double target_error) {
            return std::abs(x.mean - target) <= 4 * std::hypot(x.error, target_error) + 1e-4 * target;
        };
        CHECK(within(stats[3], e_vis, 0.0));
        CHECK(within(stats[4], e_all, 0.0));
        CHECK(within(stats[5], t_vis.mean, t_vis.standard_error));
        CHECK(within(stats[6], t_all.mean, t_all.standard_error));
        CHECK(within(stats[7], t_vis_f.mean, t_vis_f.standard_error));
        CHECK(within(stats[8], t_all_f.mean, t_all_f.standard_error));
    }
}

}  // namespace ltc_test_shade_shadowed
