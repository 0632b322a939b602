// ltc/fitting/fit_integrals.hpp -- fitting one node to the integral objective of
// ltc/fitting/integral_objective.hpp (options::goal = objective::integrals), or to that
// objective plus the squared relative L3 distance of ltc/fitting/error_metric.hpp
// (objective::combined); ltc/fitting/fit_node.hpp dispatches here when options::goal is not l3.
//
// Same matrix and minimizer as the L3 fit (fit_node.hpp): Nelder-Mead on (log m11, log m22,
// m13 / m11, m31) (1 parameter at normal incidence, 3 with options::parameters = 3), plus, with
// options::fit_magnitude, log k for a scale k of the magnitude (the stored magnitude and Fresnel
// term are both multiplied by k: the fifth degree of freedom of an isotropic lobe, since M
// itself is only defined up to scale). The GGX integrals are computed once per node; the
// options::rounds rounds restart Nelder-Mead with a simplex 4 times smaller (for combined, each round
// also re-centres the L3 estimator's proposal, as the L3 fit does).
#pragma once

#include <ltc/config.hpp>

#include <ltc/fitting/error_metric.hpp>
#include <ltc/fitting/integral_objective.hpp>
#include <ltc/fitting/ltc_parameters.hpp>
#include <ltc/fitting/moments.hpp>
#include <ltc/fitting/nelder_mead.hpp>
#include <ltc/fitting/options.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

LTC_NAMESPACE_BEGIN
namespace fit {

struct integral_fit {
    ltc_parameters parameters;
    double magnitude_scale = 1;  ///< k (1 unless options::fit_magnitude)
    double value = 0;            ///< the objective at the solution
    int evaluations = 0;
};

namespace detail {

/// u = (log m11[, log m22, m13 / m11[, m31]][, log k]): `dims` matrix parameters (1, 3 or 4),
/// then log k when `scaled`; held in 5 slots whatever the Nelder-Mead dimension.
using integral_vector = std::array<double, 5>;

inline integral_vector integral_to_vector(const ltc_parameters& p, double k, int dims) {
    integral_vector u{};
    u[0] = std::log(p.m11);
    if (dims > 1) u[1] = std::log(p.m22), u[2] = p.m13 / p.m11;
    if (dims == 4) u[3] = p.m31;
    u[std::size_t(dims)] = std::log(k);
    return u;
}

inline ltc_parameters integral_from_vector(const integral_vector& u, int dims, bool scaled, const glm::dvec3& axis,
                                           double& k) {
    ltc_parameters p;
    p.axis = axis;
    p.m11 = std::exp(u[0]);
    p.m22 = p.m11;
    if (dims > 1) p.m22 = std::exp(u[1]), p.m13 = u[2] * p.m11;
    if (dims == 4) p.m31 = u[3];
    k = scaled ? std::exp(u[std::size_t(dims)]) : 1.0;
    return p;
}

template <std::size_t Dim, typename Objective>
void minimize_integrals(integral_fit& fit, int dims, double step, const options& opt, const Objective& objective) {
    const bool scaled = Dim > std::size_t(dims);
    const auto widen = [](const std::array<double, Dim>& u) {
        integral_vector w{};
        for (std::size_t i = 0; i < Dim; ++i) w[i] = u[i];
        return w;
    };
    const integral_vector w0 = integral_to_vector(fit.parameters, fit.magnitude_scale, dims);
    std::array<double, Dim> u0{}, steps{};
    for (std::size_t i = 0; i < Dim; ++i) u0[i] = w0[i];
    steps.fill(step);
    const glm::dvec3 axis = fit.parameters.axis;
    const auto f = [&](const std::array<double, Dim>& u) {
        double k = 1;
        const ltc_parameters p = integral_from_vector(widen(u), dims, scaled, axis, k);
        if (!(p.m11 > 0) || !(p.m22 > 0) || !(p.m11 - p.m13 * p.m31 > 0) || !std::isfinite(p.m11) ||
            !std::isfinite(p.m22) || !std::isfinite(k))
            return std::numeric_limits<double>::infinity();
        const structured_inverse inv = invert_structured(p.matrix());
        if (!inv.ok) return std::numeric_limits<double>::infinity();
        return objective(inv.inverse, k);
    };
    const auto r = nelder_mead<Dim>(f, u0, steps, opt.tolerance, opt.max_evaluations);
    fit.evaluations += r.evaluations;
    fit.value = r.value;
    fit.parameters = integral_from_vector(widen(r.x), dims, scaled, axis, fit.magnitude_scale);
}

}  // namespace detail

/// Fits the node of view V, roughness alpha and moments `mom` to options::goal (integrals or
/// combined), from `start` (whose axis is kept: the average direction, or +z when isotropic).
template <template <typename> class Brdf>
integral_fit fit_integrals(const glm::dvec3& V, double alpha, const moments& mom, bool isotropic,
                           const ltc_parameters& start, const options& opt) {
    const integral_targets targets = make_integral_targets<Brdf>(V, alpha, start.axis, mom.magnitude);
    const bool combined = opt.goal == objective::combined;
    const int dims = isotropic ? 1 : (opt.parameters == 3 ? 3 : 4);
    integral_fit fit;
    fit.parameters = start;
    sample_set samples;
    double step = opt.initial_step;
    for (int round = 0; round < std::max(1, opt.rounds); ++round) {
        double f3 = 1;
        if (combined) {
            make_sample_set<Brdf>(V, alpha, fit.parameters.matrix(), opt.error_samples, samples);
            f3 = samples.all(invert_structured(fit.parameters.matrix()).inverse, mom.magnitude).f3;
            if (!(f3 > 0)) f3 = 1;
        }
        const auto objective = [&](const glm::dmat3& m_inv, double k) {
            const double m = mom.magnitude * k;
            double e = integral_loss(targets, m_inv, m);
            if (combined) {
                const double l3 = std::cbrt(samples.l3(m_inv, m) / f3);
                e += l3 * l3;
            }
            return e;
        };
        const int total = dims + (opt.fit_magnitude ? 1 : 0);
        switch (total) {
            case 1: detail::minimize_integrals<1>(fit, dims, step, opt, objective); break;
            case 2: detail::minimize_integrals<2>(fit, dims, step, opt, objective); break;
            case 3: detail::minimize_integrals<3>(fit, dims, step, opt, objective); break;
            case 4: detail::minimize_integrals<4>(fit, dims, step, opt, objective); break;
            default: detail::minimize_integrals<5>(fit, dims, step, opt, objective); break;
        }
        step *= 0.25;
    }
    return fit;
}

}  // namespace fit
LTC_NAMESPACE_END
