// ltc/reference/ground_truth.hpp -- Monte Carlo ground truth for polygonal lights: the integral of a BRDF
// model's rho(V, L) cos(theta_L) over a spherical polygon, with its standard error: the reference
// that the LTC shading is compared against (paper section 4's target, integrated over a polygon
// instead of fitted).
//
//   #include <ltc/reference/ground_truth.hpp>
//   #include <ltc/brdf/ggx.hpp>
//   ltc::ground_truth::options opt;                      // samples, seed, heuristic, ...
//   ltc::ground_truth::estimate e = ltc::ground_truth::integrate(
//       ltc::brdf::ggx<double>{}, V, alpha, vertices, n, opt);
//   // e.mean +- e.standard_error, after e.samples iterations
//
// Conventions: double, the local shading frame of ltc/brdf/model.hpp (N = +z, V.z > 0); the
// two-sided integral, whatever the winding. Degenerate cases: a polygon of no solid angle gives
// the zero estimate. Not for a renderer's hot path (one small vector per polygon).
#pragma once

#include <ltc/config.hpp>

#include <ltc/detail/math.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/reference/spherical_polygon.hpp>   // spherical_polygon
#include <ltc/reference/spherical_triangle.hpp>  // spherical_triangle_sampler, sample_spherical_triangle
#include <ltc/reference/splitmix64.hpp>          // splitmix64

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

LTC_NAMESPACE_BEGIN
namespace ground_truth {

/// How the two techniques are weighted: balance (p_k / sum p) or power (p_k^2 / sum p^2).
enum class heuristic { balance, power };

/// Which techniques run (both = MIS; the single ones are for tests and comparisons).
enum class techniques { mis, brdf_only, polygon_only };

struct options {
    std::uint64_t samples = 1u << 16;  ///< iterations (one draw per technique each), or a batch
    std::uint64_t seed = 1;
    heuristic weighting = heuristic::balance;
    techniques use = techniques::mis;
    /// Adaptive mode when either target is > 0: batches of `samples` iterations until
    /// standard_error <= max(target_relative_error * |mean|, target_absolute_error), or
    /// max_samples iterations.
    double target_relative_error = 0.0;
    double target_absolute_error = 0.0;
    std::uint64_t max_samples = 1u << 24;
};

/// mean +- standard_error: an unbiased estimate of the integral and its standard error.
struct estimate {
    double mean = 0.0;
    double standard_error = 0.0;
    std::uint64_t samples = 0;
};

/// Monte Carlo estimate of int_P model.eval(V, L, alpha) dL over the spherical polygon
/// vertices[0..n) (local frame, N = +z). Model: any type with eval/pdf/sample as in
/// ltc/brdf/model.hpp for T = double, called through an instance so that stateful models work.
///
/// Estimator. Each iteration draws one direction from each of two techniques and combines them
/// with multiple importance sampling (Veach and Guibas 1995; one sample per technique, so
/// the balance heuristic weight of technique k is p_k / (p_brdf + p_polygon)):
///   - BRDF sampling: L ~ model.sample(V, u, alpha), density model.pdf(V, L, alpha);
///   - polygon sampling: L uniform in solid angle over the spherical polygon
///     (ltc/reference/spherical_polygon.hpp).
/// The integrand is model.eval(V, L, alpha) times the polygon's indicator, so the estimate is
/// the integral over the *set* of directions that the polygon covers, whatever its winding:
/// the two-sided integral. A one-sided light is 0 from behind; multiply by the facing yourself.
/// The iterations are independent, so the standard error is the sample standard deviation of
/// the per-iteration values over sqrt(iterations) (Welford's update, in double).
///
/// The pieces, each of which can be included on its own:
///   ltc/reference/splitmix64.hpp          splitmix64, the seeded random numbers
///   ltc/reference/spherical_triangle.hpp  spherical_triangle_sampler, sample_spherical_triangle
///                                         (Arvo 1995)
///   ltc/reference/spherical_polygon.hpp   spherical_polygon: polygon sampling, its density and
///                                         the winding number
///
/// Determinism: a fixed seed gives the same random numbers on every platform (SplitMix64,
/// doubles from the top 53 bits, no <random> distribution, drawn in a sequenced order), hence
/// the same estimate up to the last-bit differences of the platform's libm.
///
/// Caveat: the standard error is estimated from the iterations, so it cannot see events that
/// have not happened. For a light much smaller than the BRDF lobe, BRDF samples hit it so rarely
/// (and then carry a tiny weight) that a run may see none; the estimate is then low by that
/// technique's share, about Omega * p_brdf / (1 + Omega * p_brdf) of the integral (1.5e-5 for the
/// 5e-5 sr triangle of the tests), which the standard error does not include.
template <typename Model>
estimate integrate(const Model& model, const glm::dvec3& V, double alpha, const glm::dvec3* vertices,
                   std::size_t n, const options& opt = {});

/// The same for a model whose parameter is not a scalar, such as brdf::ggx_anisotropic<double>
/// with brdf::anisotropic_alpha<double>{alpha_x, alpha_y}: alpha goes to eval, pdf and sample as
/// given. (Scalar alphas take the overload above, unchanged.)
template <typename Model, typename Alpha,
          typename = std::enable_if_t<!std::is_convertible<const Alpha&, double>::value>>
estimate integrate(const Model& model, const glm::dvec3& V, const Alpha& alpha, const glm::dvec3* vertices,
                   std::size_t n, const options& opt = {});

}  // namespace ground_truth

namespace detail {

/// ground_truth::integrate for a model parameter alpha of any type.
template <typename Model, typename Alpha>
ground_truth::estimate integrate_polygon_mis(const Model& model, const glm::dvec3& V, const Alpha& alpha,
                                             const glm::dvec3* vertices, std::size_t n,
                                             const ground_truth::options& opt) {
    using namespace ground_truth;  // options, estimate, spherical_polygon, splitmix64, ...
    const spherical_polygon poly(vertices, n);
    estimate e;
    if (poly.empty()) return e;  // no solid angle: the integral is 0
    splitmix64 rng(opt.seed);
    const bool use_brdf = opt.use != techniques::polygon_only;
    const bool use_poly = opt.use != techniques::brdf_only;
    const auto weight = [&](double p, double q) {  // MIS weight of the technique with density p
        if (opt.use != techniques::mis) return 1.0;
        if (opt.weighting == heuristic::power) {
            const double m = glm::max(p, q);  // scale to avoid overflow of the squares
            const double a = p / m, b = q / m;
            return a * a / (a * a + b * b);
        }
        return p / (p + q);
    };
    double mean = 0.0, m2 = 0.0;
    std::uint64_t count = 0;
    const std::uint64_t batch = opt.samples > 0 ? opt.samples : 1;
    for (;;) {
        for (std::uint64_t it = 0; it < batch; ++it) {
            double x = 0.0;
            if (use_brdf) {
                const glm::dvec2 u = rng.uniform2();
                const glm::dvec3 L = model.sample(V, u, alpha);
                const double p_b = model.pdf(V, L, alpha);
                bool in = false;
                double p_p = 0.0;
                if (p_b > 0.0) poly.classify(L, in, p_p);
                if (in) {
                    const double f = model.eval(V, L, alpha);
                    if (f > 0.0) x += weight(p_b, use_poly ? p_p : 0.0) * f / p_b;
                }
            }
            if (use_poly) {
                const glm::dvec3 u = rng.uniform3();
                const glm::dvec3 L = poly.sample(u);
                bool in = false;
                double p_p = 0.0;
                poly.classify(L, in, p_p);
                if (p_p > 0.0 && in) {
                    const double f = model.eval(V, L, alpha);
                    if (f > 0.0) x += weight(p_p, use_brdf ? model.pdf(V, L, alpha) : 0.0) * f / p_p;
                }
            }
            ++count;
            const double d = x - mean;
            mean += d / static_cast<double>(count);
            m2 += d * (x - mean);
        }
        const double var = count > 1 ? m2 / static_cast<double>(count - 1) : 0.0;
        e.mean = mean;
        e.standard_error = std::sqrt(var / static_cast<double>(count));
        e.samples = count;
        const bool adaptive = opt.target_relative_error > 0.0 || opt.target_absolute_error > 0.0;
        if (!adaptive || count >= opt.max_samples ||
            e.standard_error <= glm::max(opt.target_relative_error * std::abs(e.mean), opt.target_absolute_error))
            break;
    }
    return e;
}

}  // namespace detail

namespace ground_truth {

template <typename Model>
estimate integrate(const Model& model, const glm::dvec3& V, double alpha, const glm::dvec3* vertices,
                   std::size_t n, const options& opt) {
    return detail::integrate_polygon_mis(model, V, alpha, vertices, n, opt);
}

template <typename Model, typename Alpha, typename>
estimate integrate(const Model& model, const glm::dvec3& V, const Alpha& alpha, const glm::dvec3* vertices,
                   std::size_t n, const options& opt) {
    return detail::integrate_polygon_mis(model, V, alpha, vertices, n, opt);
}

}  // namespace ground_truth
LTC_NAMESPACE_END
