// ltc/fitting/fit_node.hpp -- fitting the LTC of one table node (fit_node, paper section 4): the
// BRDF's moments (ltc/fitting/moments.hpp), then options::rounds rounds of Nelder-Mead on the
// L3 error of a frozen sample set (ltc/fitting/error_metric.hpp); or, with options::goal set to
// objective::integrals or combined, the integral objective (ltc/fitting/fit_integrals.hpp).
//
// Minimizer: Nelder-Mead (Lagarias et al. 1998 variant, standard coefficients 1, 2, 1/2, 1/2;
// ltc/fitting/nelder_mead.hpp) on (log m11, log m22, m13 / m11, m31), a parameterization in
// which the lobe width is scale-free from alpha = 1e-4 to 1, terminated when the objective's
// relative spread over the simplex falls below options::tolerance or after
// options::max_evaluations evaluations. (The paper's code release keeps m31 = 0 and fits 3
// parameters; options::parameters = 3 does the same.) At normal incidence the lobe is
// rotationally symmetric and M = diag(m, m, 1) has one parameter.
#pragma once

#include <ltc/config.hpp>

#include <ltc/brdf/model.hpp>
#include <ltc/fitting/error_metric.hpp>
#include <ltc/fitting/fit_integrals.hpp>
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

struct node_result {
    ltc_parameters parameters;  ///< the fit, in its rotated frame
    glm::dmat3 m_inv{1.0};      ///< M^-1 / M^-1[1][1] (the stored matrix)
    double magnitude = 0;       ///< integral of rho cos
    double fresnel = 0;         ///< integral of rho cos (1 - V.H)^5
    double error = 0;           ///< the L3 objective at the solution (last round's estimator)
    double relative_l1 = 0;     ///< integral |f - m D| / integral f (same estimator)
    double relative_l3 = 0;     ///< (integral |f - m D|^3 / integral f^3)^(1/3) (same estimator)
    int evaluations = 0;        ///< objective evaluations, all rounds
};

namespace detail {

/// Parameters from the Nelder-Mead vector (log m11, log m22, m13 / m11, m31); `dims` = 1
/// (isotropic), 3 or 4.
inline ltc_parameters from_vector(const double* u, int dims, const glm::dvec3& axis) {
    ltc_parameters p;
    p.axis = axis;
    p.m11 = std::exp(u[0]);
    if (dims == 1) {
        p.m22 = p.m11;
        return p;
    }
    p.m22 = std::exp(u[1]);
    p.m13 = u[2] * p.m11;
    if (dims == 4) p.m31 = u[3];
    return p;
}

inline void to_vector(const ltc_parameters& p, int dims, double* u) {
    u[0] = std::log(p.m11);
    if (dims == 1) return;
    u[1] = std::log(p.m22);
    u[2] = p.m13 / p.m11;
    if (dims == 4) u[3] = p.m31;
}

template <std::size_t Dim>
ltc_parameters minimize(const sample_set& samples, double magnitude, const ltc_parameters& start, double step,
                        const options& opt, int& evaluations, double& value) {
    const int dims = int(Dim);
    std::array<double, Dim> u0{}, steps{};
    to_vector(start, dims, u0.data());
    steps.fill(step);
    const auto objective = [&](const std::array<double, Dim>& u) {
        const ltc_parameters p = from_vector(u.data(), dims, start.axis);
        if (!(p.m11 > 0) || !(p.m22 > 0) || !(p.m11 - p.m13 * p.m31 > 0) || !std::isfinite(p.m11) ||
            !std::isfinite(p.m22))
            return std::numeric_limits<double>::infinity();
        const structured_inverse inv = invert_structured(p.matrix());
        if (!inv.ok) return std::numeric_limits<double>::infinity();
        return samples.l3(inv.inverse, magnitude);
    };
    const auto r = nelder_mead<Dim>(objective, u0, steps, opt.tolerance, opt.max_evaluations);
    evaluations += r.evaluations;
    value = r.value;
    return from_vector(r.x.data(), dims, start.axis);
}

}  // namespace detail

namespace detail {

template <template <typename> class Brdf>
node_result fit_from(const glm::dvec3& V, double alpha, const moments& mom, bool isotropic, ltc_parameters p,
                     const options& opt) {
    node_result r;
    r.magnitude = mom.magnitude;
    r.fresnel = mom.fresnel;
    sample_set samples;
    if (opt.goal != objective::l3) {  // ltc/fitting/fit_integrals.hpp (opt-in)
        const integral_fit f = fit_integrals<Brdf>(V, alpha, mom, isotropic, p, opt);
        p = f.parameters;
        r.magnitude *= f.magnitude_scale;
        r.fresnel *= f.magnitude_scale;
        r.error = f.value;
        r.evaluations = f.evaluations;
        make_sample_set<Brdf>(V, alpha, p.matrix(), opt.error_samples, samples);  // for relative_l1/l3
    }
    double step = opt.initial_step;
    for (int round = 0; opt.goal == objective::l3 && round < std::max(1, opt.rounds); ++round) {
        make_sample_set<Brdf>(V, alpha, p.matrix(), opt.error_samples, samples);
        if (isotropic)
            p = minimize<1>(samples, r.magnitude, p, step, opt, r.evaluations, r.error);
        else if (opt.parameters == 3)
            p = minimize<3>(samples, r.magnitude, p, step, opt, r.evaluations, r.error);
        else
            p = minimize<4>(samples, r.magnitude, p, step, opt, r.evaluations, r.error);
        step *= 0.25;
    }
    r.parameters = p;
    const glm::dmat3 M = p.matrix();
    r.m_inv = normalized_inverse(M);
    const auto s = samples.all(invert_structured(M).inverse, r.magnitude);
    r.relative_l1 = s.f1 > 0 ? s.l1 / s.f1 : 0.0;
    r.relative_l3 = s.f3 > 0 ? std::cbrt(s.l3 / s.f3) : 0.0;
    return r;
}

}  // namespace detail

/// Fits the LTC of one node: view cos(theta_v) (V = (sin, 0, cos)), roughness alpha, starting
/// from `start` (whose axis is replaced by the BRDF's average direction). At normal incidence
/// (cos_theta == 1) the fit is isotropic: M = diag(m, m, 1), axis +z, start.m11 used.
/// Safeguard: a fit whose relative L1 error exceeds 1 (worse than no lobe at all: the start
/// was in another basin, which happens when the neighbours of a coarse table are far apart)
/// is redone from a fresh start, an isotropic lobe of width alpha on the average direction,
/// and the better of the two is kept. (It never triggers for the shipped 64 x 64 table.) With
/// options::goal other than l3, a node still worse than no lobe is fitted with L3 instead.
template <template <typename> class Brdf>
node_result fit_node(double cos_theta, double alpha, const ltc_parameters& start, const options& opt) {
    const glm::dvec3 V = brdf::view_from_cos(cos_theta);
    const moments mom = compute_moments<Brdf>(V, alpha, opt.moment_samples);
    const bool isotropic = cos_theta >= 1.0;
    ltc_parameters p = start;
    if (isotropic) {
        p.axis = glm::dvec3(0, 0, 1);
        p.m22 = p.m11;
        p.m13 = p.m31 = 0;
    } else {
        p.axis = mom.average_direction;
        if (opt.parameters == 3) p.m31 = 0;
    }
    node_result r = detail::fit_from<Brdf>(V, alpha, mom, isotropic, p, opt);
    if (!(r.relative_l1 <= 1.0)) {
        ltc_parameters fresh;
        fresh.axis = p.axis;
        fresh.m11 = fresh.m22 = std::min(std::max(alpha, 1e-6), 1.0);
        node_result alt = detail::fit_from<Brdf>(V, alpha, mom, isotropic, fresh, opt);
        alt.evaluations += r.evaluations;
        if (alt.relative_l1 < r.relative_l1 || !(r.relative_l1 == r.relative_l1)) r = alt;
        else r.evaluations = alt.evaluations;
    }
    if (opt.goal != objective::l3 && !(r.relative_l1 <= 1.0)) {
        // The integral objective barely constrains a sliver of a lobe at the horizon (64 x 64 GGX
        // table: 14 nodes, cos theta_v < 0.032 and alpha < 0.031): the L3 fit instead.
        options l3 = opt;
        l3.goal = objective::l3;
        node_result alt = detail::fit_from<Brdf>(V, alpha, mom, isotropic, p, l3);
        alt.evaluations += r.evaluations;
        r = alt;
    }
    return r;
}

}  // namespace fit
LTC_NAMESPACE_END
