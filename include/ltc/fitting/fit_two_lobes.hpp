// ltc/fitting/fit_two_lobes.hpp -- fitting a node with a *sum of two* LTCs, where one linearly
// transformed cosine cannot follow GGX (at grazing views and low roughness):
//
//   f = rho cos ~= magnitude * ((1 - s) D_1 + s D_2),   D_i the LTC of M_i, s in (0, 1),
//
// each D_i integrated over a polygon exactly (eq. 3), so the shading integral stays closed form
// (one more LTC integral, no second form factor). M_1 and M_2 have the structure of
// ltc/fitting/ltc_parameters.hpp; s is the second lobe's share. The model ltc_and_cosine fixes
// lobe 1 at the clamped cosine about the normal (M_1 = I), whose integral is the form factor.
//
//   ltc::fit::two_lobe_result r = ltc::fit::fit_two_lobes<ltc::brdf::ggx>(cos_theta, alpha, start, opt);
//   ltc::fit::two_lobe_table t = ltc::fit::fit_two_lobe_table<ltc::brdf::ggx>(opt);
//
// Conventions: double, the node layout of ltc/fitting/fit.hpp. Degenerate cases: a lobe left with
// almost no share is dropped (fit_two_lobes); a node on a plateau is refitted as a single lobe.
#pragma once

#include <ltc/config.hpp>

#include <ltc/brdf/model.hpp>
#include <ltc/brdf/schlick.hpp>
#include <ltc/fitting/error_metric.hpp>
#include <ltc/fitting/fit_node.hpp>
#include <ltc/fitting/fit_table.hpp>
#include <ltc/fitting/integral_objective.hpp>
#include <ltc/fitting/ltc_parameters.hpp>
#include <ltc/fitting/moments.hpp>
#include <ltc/fitting/nelder_mead.hpp>
#include <ltc/fitting/options.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <vector>

LTC_NAMESPACE_BEGIN
namespace fit {

/// What the two lobes are: two free LTCs, or lobe 1 fixed at the clamped cosine about the normal
/// (M_1 = I, its integral the form factor) and lobe 2 a free LTC. With ltc_and_cosine,
///
///   f = rho cos ~= magnitude * ((1 - s) D_cos + s D_M),
///
/// whose integral over a polygon is the form factor, which the shading computes anyway for the
/// diffuse term: one LTC's cost, with a share of GGX's lobe moved to the broad part that a single
/// LTC cannot follow (ltc/shading/cosine_lobe_polygon_light.hpp). The same objective fits D_M and
/// s (5 numbers), its integrals over the spiral family with the floor at the significance
/// threshold (integral_family::spiral(), ltc/fitting/integral_objective.hpp: the tails, where the
/// cosine's share shows, count), each node from its own one-lobe fit with s = 0.9
/// (start_with_cosine; not marched along the rows as the two-LTC table is: docs/design_notes.md).
enum class two_lobe_model { two_ltcs, ltc_and_cosine };

struct two_lobe_result {
    std::array<ltc_parameters, 2> lobes;               ///< in their rotated frame
    std::array<glm::dmat3, 2> m_inv{glm::dmat3(1.0), glm::dmat3(1.0)};  ///< M_i^-1 / M_i^-1[1][1]
    double share = 0;                                  ///< s: the second lobe's share of the magnitude
    double fresnel_share = 0;                          ///< s_F: its share of the Fresnel term (fresnel_share_of)
    double magnitude = 0;                              ///< integral of rho cos
    double fresnel = 0;                                ///< integral of rho cos (1 - V.H)^5
    double value = 0;                                  ///< the objective at the solution (before a lobe is dropped)
    int evaluations = 0;
    bool stalled = false;  ///< Nelder-Mead stopped on its first simplex in every round (a plateau)
    two_lobe_model model = two_lobe_model::two_ltcs;
};

namespace detail {

/// f, and the balance-heuristic weight over the BRDF's sampler and both lobes' samplers.
struct mixture_samples {
    std::vector<double> x, y, z, f, w;

    template <template <typename> class Brdf>
    void make(const glm::dvec3& V, double alpha, const glm::dmat3& M1, const glm::dmat3& M2, int n) {
        using B = Brdf<double>;
        const structured_inverse i1 = invert_structured(M1), i2 = invert_structured(M2);
        const double count = double(n) * double(n);
        x.clear(), y.clear(), z.clear(), f.clear(), w.clear();
        const auto add = [&](const glm::dvec3& L) {
            const double fv = L.z > 0 ? B::eval(V, L, alpha) : 0.0;
            const double p = count * (B::pdf(V, L, alpha) + ltc_density(i1.inverse, 1.0 / i1.abs_determinant, L) +
                                      ltc_density(i2.inverse, 1.0 / i2.abs_determinant, L));
            if (p > 0 && std::isfinite(p) && std::isfinite(fv))
                x.push_back(L.x), y.push_back(L.y), z.push_back(L.z), f.push_back(fv), w.push_back(1.0 / p);
        };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::dvec2 u((i + 0.5) / n, (j + 0.5) / n);
                add(B::sample(V, u, alpha));
                add(normalize_or_zero(M1 * sample_cosine(u)));
                add(normalize_or_zero(M2 * sample_cosine(u)));
            }
    }

    /// The estimate of the integral of f^3 (once per proposal: the objective's normalization).
    double f3() const {
        double s = 0;
        for (std::size_t i = 0; i < f.size(); ++i) s += w[i] * f[i] * f[i] * f[i];
        return s;
    }

    /// The estimate of the integral of |f - g|^3, g = k1 D_1 + k2 D_2 (m_inv_i structured).
    double l3(const glm::dmat3& m1, double k1, const glm::dmat3& m2, double k2) const {
        const auto lobe = [](const glm::dmat3& m, double k, double xs, double ys, double zs) {
            const double a = m[0][0], b = m[2][0], c = m[1][1], d = m[0][2], e = m[2][2];
            const double X = a * xs + b * zs, Y = c * ys, Z = d * xs + e * zs;
            const double l2 = X * X + Y * Y + Z * Z;
            return k * std::max(Z, 0.0) / (l2 * l2);
        };
        const double c1 = k1 * std::abs(m1[1][1] * (m1[0][0] * m1[2][2] - m1[2][0] * m1[0][2])) / pi<double>();
        const double c2 = k2 * std::abs(m2[1][1] * (m2[0][0] * m2[2][2] - m2[2][0] * m2[0][2])) / pi<double>();
        double e3 = 0;
        for (std::size_t i = 0; i < f.size(); ++i) {
            const double g = lobe(m1, c1, x[i], y[i], z[i]) + lobe(m2, c2, x[i], y[i], z[i]);
            const double d = std::abs(f[i] - g);
            e3 += w[i] * d * d * d;
        }
        return e3;
    }
};

inline double logistic(double t) { return 1.0 / (1.0 + std::exp(-t)); }

/// Nelder-Mead over the first Dim of the 9 numbers (the others stay as in u0).
template <std::size_t Dim, typename F>
nelder_mead_result<9> minimize_padded(const F& objective, const std::array<double, 9>& u0, double step, double tolerance,
                                      int max_evaluations) {
    std::array<double, Dim> start{}, steps{};
    for (std::size_t i = 0; i < Dim; ++i) start[i] = u0[i];
    steps.fill(step);
    const auto widen = [&](const std::array<double, Dim>& u) {
        std::array<double, 9> w = u0;
        for (std::size_t i = 0; i < Dim; ++i) w[i] = u[i];
        return w;
    };
    const auto r = nelder_mead<Dim>([&](const std::array<double, Dim>& u) { return objective(widen(u)); }, start, steps,
                                    tolerance, max_evaluations);
    nelder_mead_result<9> out;
    out.x = widen(r.x);
    out.value = r.value;
    out.evaluations = r.evaluations;
    return out;
}

}  // namespace detail

/// The edge terms of the objective's LTC integrals: the double-accurate polynomial_double
/// (ltc/core/edge_policy.hpp) instead of atan2, which is slower. The float-accurate
/// minimax_rational would be faster still, but perturbing the objective by 4e-8 moves nearly every
/// node within Nelder-Mead's tolerance (docs/design_notes.md: the comparison).
using objective_edge_policy = edge_policy::polynomial_double;

/// Where a two-lobe fit starts: both lobes (their axes are replaced by the node's average
/// direction), the second lobe's share and the model.
struct two_lobe_start {
    std::array<ltc_parameters, 2> lobes;
    double share = 0.2;
    two_lobe_model model = two_lobe_model::two_ltcs;  ///< ltc_and_cosine: lobes[0] is ignored (the cosine)
};

/// The start from a one-lobe fit (fit_node): lobe 1 as fitted, lobe 2 twice as wide, share 0.2.
inline two_lobe_start start_from_one_lobe(const ltc_parameters& one) {
    two_lobe_start s;
    s.lobes[0] = one;
    s.lobes[1] = one;
    s.lobes[1].m11 *= 2.0;
    s.lobes[1].m22 *= 2.0;
    s.lobes[1].m13 *= 2.0;
    return s;
}

/// The start of the ltc_and_cosine model from a one-lobe fit: lobe 2 as fitted, share 0.9.
inline two_lobe_start start_with_cosine(const ltc_parameters& one) {
    two_lobe_start s;
    s.lobes[1] = one;
    s.share = 0.9;
    s.model = two_lobe_model::ltc_and_cosine;
    return s;
}

/// The start from a neighbour's two-lobe fit (marching along a table's row).
inline two_lobe_start start_from(const two_lobe_result& r) {
    two_lobe_start s;
    s.lobes = r.lobes;
    s.share = r.share;
    s.model = r.model;
    return s;
}

namespace detail {

/// The second lobe's share s_F of the Fresnel term (Hill 2016's split: the specular colour F0
/// scales magnitude F0 + fresnel (1 - F0), each lobe's part of both), fitted once the lobes are:
/// the least-squares split of the integral loss of ltc/fitting/integral_objective.hpp applied to
/// the Fresnel part of f, rho cos (1 - V.H)^5, over the node's family,
///   min over s_F in [0, 1] of sum_k ((F ((1 - s_F) I_1k + s_F I_2k) - G_k) / (G_k + floor F))^2,
/// F the fresnel channel (the Fresnel part's integral over the hemisphere, which the two lobes'
/// channels, F (1 - s_F) and F s_F, add up to whatever the split; the lobes themselves hold
/// (1 + cos beta) / 2 <= 1 of their mass above the horizon, beta the angle of M's third row to
/// z, so the shading's Fresnel energy over the whole hemisphere does move with s_F, as its
/// magnitude's does with s), G_k the Fresnel part's integrals (brdf::fresnel_part,
/// ltc/brdf/schlick.hpp), I_lk lobe l's (exact edge terms: once per node, their cost
/// does not matter here).
/// Closed form of this convex quadratic in s_F: s_F = sum a_k b_k / sum a_k^2, a_k =
/// F (I_2k - I_1k) / w_k, b_k = (G_k - F I_1k) / w_k, clamped to [0, 1] (the constrained
/// optimum). (1 - V.H)^5 grows with the angle between V and L, so the Fresnel part weighs the
/// lobe's directions farthest from V, towards the horizon beyond the mirror direction, more than
/// f does, and the magnitude's split s need not suit it. The clamp binds at most nodes of the
/// shipped tables (docs/design_notes.md): mostly the whole Fresnel term on one lobe, which can
/// change between neighbouring nodes. Where the lobes coincide (a dropped lobe:
/// s = 0, or s = 1 with two LTCs) s_F = s.
/// `t`: the Fresnel part's targets over the node's family (make_integral_targets_with_fresnel).
inline double fresnel_share_of(const integral_targets& t, const two_lobe_result& r) {
    if (!(r.share > 0) || !(r.fresnel > 0)) return r.share;
    std::vector<double> i1(t.polygons.size()), i2(t.polygons.size());
    ltc_integrals(t, r.m_inv[0], i1.data());
    ltc_integrals(t, r.m_inv[1], i2.data());
    const double F = r.fresnel, floor = t.floor * F;
    double aa = 0, ab = 0;
    for (std::size_t k = 0; k < t.polygons.size(); ++k) {
        const double w = t.ggx[k] + floor;
        const double a = F * (i2[k] - i1[k]) / w, b = (t.ggx[k] - F * i1[k]) / w;
        aa += a * a, ab += a * b;
    }
    if (!(aa > 0) || !std::isfinite(ab / aa)) return r.share;
    return std::min(std::max(ab / aa, 0.0), 1.0);
}

}  // namespace detail

/// Fits the two-lobe node of view cos(theta_v) and roughness alpha from `start`; with
/// `refit_first` false, lobe 1 stays as in `start` and only lobe 2 and the share are fitted
/// (5 numbers; the tables refit both: docs/design_notes.md). With start.model ltc_and_cosine,
/// lobe 1 is the cosine and stays fixed whatever `refit_first` says.
///
/// Objective: the integral loss of ltc/fitting/integral_objective.hpp applied to the mixture,
/// plus the squared relative L3 distance of the mixture to f (the combined objective of
/// fit_integrals.hpp, written for two lobes): the L3 term keeps the peak, the integrals the
/// tails. The L3 distance is estimated by MIS (balance heuristic) over three n x n midpoint sets:
/// the BRDF's sampler and each lobe's (Algorithm 1), frozen for a round and re-centred on the
/// round's result, as in ltc/fitting/error_metric.hpp. Minimizer: Nelder-Mead on the 9 numbers
/// (3 at normal incidence, where both lobes are isotropic; 4 parameters per lobe about the BRDF's
/// average direction, and the share s parameterized by its logit), from lobe 1 = the one-lobe fit
/// and lobe 2 = lobe 1 twice as wide with share 0.2 (start_from_one_lobe).
///
/// The Fresnel term (Hill 2016: the integral of rho cos (1 - V.H)^5, which a specular colour F0
/// weighs by 1 - F0) is split between the lobes by a fit of its own once the lobes are fitted
/// (detail::fresnel_share_of: a least-squares share in closed form), not by the magnitude's share
/// s: its integrand weighs other parts of the lobe.
///
/// A lobe left with under 1e-3 of the magnitude is dropped: it becomes a copy of the other, with
/// share 0 (with the cosine as lobe 1, a dead LTC becomes the cosine).
template <template <typename> class Brdf>
two_lobe_result fit_two_lobes(double cos_theta, double alpha, const two_lobe_start& start, const options& opt,
                              bool refit_first = true) {
    const glm::dvec3 V = brdf::view_from_cos(cos_theta);
    const moments mom = compute_moments<Brdf>(V, alpha, opt.moment_samples);
    const bool isotropic = cos_theta >= 1.0;
    const int dims = isotropic ? 1 : 4;
    const glm::dvec3 axis = isotropic ? glm::dvec3(0, 0, 1) : mom.average_direction;

    two_lobe_result r;
    r.magnitude = mom.magnitude;
    r.fresnel = mom.fresnel;
    r.lobes = start.lobes;
    for (ltc_parameters& p : r.lobes) {
        p.axis = axis;
        if (isotropic) p.m22 = p.m11, p.m13 = p.m31 = 0;
    }
    r.share = std::min(std::max(start.share, 1e-6), 1 - 1e-6);
    r.model = start.model;
    const bool with_cosine = start.model == two_lobe_model::ltc_and_cosine;
    if (with_cosine) r.lobes[0] = ltc_parameters{}, refit_first = false;  // M_1 = I, about the normal

    // The Fresnel part's targets come from the same pass of the quadrature (fresnel_share_of).
    const auto both = make_integral_targets_with_fresnel<Brdf>(
        V, alpha, axis, mom.magnitude, mom.fresnel, with_cosine ? integral_family::spiral() : integral_family::rings());
    const integral_targets& targets = both.first;
    std::vector<double> i1(targets.polygons.size()), i2(targets.polygons.size());
    detail::mixture_samples samples;

    constexpr std::size_t N = 9;
    using vec = std::array<double, N>;
    // (lobe 1, lobe 2, logit s), or with lobe 1 fixed (lobe 2, logit s).
    const ltc_parameters first = r.lobes[0];
    const auto to_vec = [&]() {
        vec u{};
        if (!refit_first) {
            detail::to_vector(r.lobes[1], dims, &u[0]);
            u[std::size_t(dims)] = std::log(r.share / (1.0 - r.share));
            return u;
        }
        for (int l = 0; l < 2; ++l) detail::to_vector(r.lobes[std::size_t(l)], dims, &u[std::size_t(l * dims)]);
        u[std::size_t(2 * dims)] = std::log(r.share / (1.0 - r.share));
        return u;
    };
    const auto from_vec = [&](const vec& u, ltc_parameters* p, double& s) {
        if (!refit_first) {
            p[0] = first;
            p[1] = detail::from_vector(&u[0], dims, axis);
            s = detail::logistic(u[std::size_t(dims)]);
            return;
        }
        for (int l = 0; l < 2; ++l) p[l] = detail::from_vector(&u[std::size_t(l * dims)], dims, axis);
        s = detail::logistic(u[std::size_t(2 * dims)]);
    };
    if (!refit_first) ltc_integrals<objective_edge_policy>(targets, invert_structured(first.matrix()).inverse, i1.data());

    double step = opt.initial_step;
    bool moved = false;
    for (int round = 0; round < std::max(1, opt.rounds); ++round) {
        samples.make<Brdf>(V, alpha, r.lobes[0].matrix(), r.lobes[1].matrix(), opt.error_samples);
        double f3 = samples.f3();
        if (!(f3 > 0)) f3 = 1;
        const auto objective = [&](const vec& u) {
            ltc_parameters p[2];
            double s = 0;
            from_vec(u, p, s);
            glm::dmat3 mi[2];
            for (int l = 0; l < 2; ++l) {
                if (!(p[l].m11 > 0) || !(p[l].m22 > 0) || !(p[l].m11 - p[l].m13 * p[l].m31 > 0) ||
                    !std::isfinite(p[l].m11) || !std::isfinite(p[l].m22))
                    return std::numeric_limits<double>::infinity();
                const structured_inverse inv = invert_structured(p[l].matrix());
                if (!inv.ok) return std::numeric_limits<double>::infinity();
                mi[l] = inv.inverse;
            }
            const double m = mom.magnitude;
            if (refit_first) ltc_integrals<objective_edge_policy>(targets, mi[0], i1.data());
            ltc_integrals<objective_edge_policy>(targets, mi[1], i2.data());
            const double floor = targets.floor * m;
            double loss = 0;
            for (std::size_t k = 0; k < targets.polygons.size(); ++k) {
                const double e = (m * ((1 - s) * i1[k] + s * i2[k]) - targets.ggx[k]) / (targets.ggx[k] + floor);
                loss += e * e;
            }
            if (!targets.polygons.empty()) loss /= double(targets.polygons.size());
            const double rel = std::cbrt(samples.l3(mi[0], m * (1 - s), mi[1], m * s) / f3);
            return loss + rel * rel;
        };
        const vec u0 = to_vec();
        const int max_evaluations = opt.max_evaluations * 5;
        // The numbers fitted: each fitted lobe's dims and the share's logit (9, 5, 3 or 2).
        const int fitted = (refit_first ? 2 * dims : dims) + 1;
        const auto minimize = [&](auto dim) {
            return detail::minimize_padded<decltype(dim)::value>(objective, u0, step, opt.tolerance, max_evaluations);
        };
        const auto res = fitted == 9   ? minimize(std::integral_constant<std::size_t, 9>())
                         : fitted == 5 ? minimize(std::integral_constant<std::size_t, 5>())
                         : fitted == 3 ? minimize(std::integral_constant<std::size_t, 3>())
                                       : minimize(std::integral_constant<std::size_t, 2>());
        r.evaluations += res.evaluations;
        moved = moved || res.evaluations > fitted + 1;  // more than the first simplex
        r.value = res.value;
        from_vec(res.x, r.lobes.data(), r.share);
        step *= 0.25;
    }
    r.stalled = !moved;
    // A lobe left with under 1e-3 of the magnitude is dropped: it becomes a copy of the other,
    // with share 0. Nothing constrains such a lobe: it drifts towards a spike of huge density,
    // which the L3 term's frozen samples hit or miss at random. The next node, started from it,
    // then sees a noisy objective, and Nelder-Mead stopped on its first simplex along whole rows
    // (docs/design_notes.md). A table also interpolates a spike's matrix into its neighbours
    // (tools/ggx_error_report --grid off).
    // With the cosine as lobe 1, only the LTC can drift; a dead LTC becomes the cosine (the node
    // all cosine), and the cosine, fixed, stays whatever its share.
    constexpr double dead = 1e-3;
    if (r.share < dead) r.lobes[1] = r.lobes[0], r.share = 0;
    if (r.share > 1 - dead && !with_cosine) r.lobes[0] = r.lobes[1], r.share = 1;
    for (int l = 0; l < 2; ++l) r.m_inv[std::size_t(l)] = normalized_inverse(r.lobes[std::size_t(l)].matrix());
    r.fresnel_share = detail::fresnel_share_of(both.second, r);
    return r;
}

/// The shipped two-lobe tables' size (ltc/tables/ggx_two_lobe.hpp): 32 x 32, where the two-lobe
/// fit's cost and its error (tools/ggx_error_report, section 8) meet (docs/design_notes.md).
inline constexpr int two_lobe_default_size = 32;

/// A size x size table of two-lobe nodes (nodes[a * size + t], as ltc::fit::table).
struct two_lobe_table {
    int size = 0;
    std::vector<two_lobe_result> nodes;
    two_lobe_model model = two_lobe_model::two_ltcs;

    const two_lobe_result& at(int t, int a) const { return nodes[std::size_t(a) * std::size_t(size) + std::size_t(t)]; }

    /// Two tables of the layout of ltc/tables/ltc_table.hpp, one after the other (2 size^2 6
    /// floats): lobe l's normalized M_l^-1, the magnitude times its share ((1 - s) for lobe 1, s
    /// for lobe 2) and the Fresnel term times its share of that ((1 - s_F), s_F), so that (with
    /// two_ltcs) each is an ordinary ltc_table and the shading is the sum of the two lobes' (the
    /// shares interpolate linearly, like the magnitude).
    ///
    /// With the model ltc_and_cosine, lobe 2's four M^-1 channels are premultiplied by its
    /// magnitude channel (m s), which a lookup divides out again (ltc::ggx_cosine_lobe::fetch):
    /// the bilinear lookup then weights each node's matrix by the LTC's share there. The optimal
    /// split between the cosine and the LTC jumps between neighbouring nodes at rough, near-normal
    /// views (a node almost all cosine with a flattened LTC next to one with little cosine and an
    /// LTC close to the cosine), and the plain lookup there gave the flattened matrix to half the
    /// magnitude (tests/test_cosine_lobe.cpp; docs/design_notes.md). Subnormal values are flushed to 0, and a
    /// lobe whose magnitude channel flushes to 0 stores a zero matrix too (so that every lookup
    /// stays a convex combination of the nodes' matrices), and gives its Fresnel term to the
    /// cosine (a zero matrix reads as the cosine: ltc::ggx_cosine_lobe::unpremultiplied).
    std::vector<float> packed() const {
        const bool premultiply = model == two_lobe_model::ltc_and_cosine;
        const auto flushed = [&](double x) {
            const float f = float(x);
            return premultiply && std::abs(f) < std::numeric_limits<float>::min() ? 0.0f : f;
        };
        const auto dead_ltc = [&](const two_lobe_result& n) {
            return premultiply && flushed(n.magnitude * n.share) == 0.0f;
        };
        std::vector<float> d;
        d.reserve(2 * nodes.size() * channel::count);
        for (int l = 0; l < 2; ++l)
            for (const two_lobe_result& n : nodes) {
                const glm::dmat3& m = n.m_inv[std::size_t(l)];
                const double w = l == 0 ? 1 - n.share : n.share;
                const bool ltc_dead = dead_ltc(n);
                const bool dead = l == 1 && ltc_dead;
                const double fresnel_share = ltc_dead ? 0.0 : n.fresnel_share;
                const double p = dead ? 0.0 : premultiply && l == 1 ? n.magnitude * w : 1.0;
                d.push_back(flushed(m[0][0] * p));
                d.push_back(flushed(m[0][2] * p));
                d.push_back(flushed(m[2][0] * p));
                d.push_back(flushed(m[2][2] * p));
                d.push_back(flushed(n.magnitude * w));
                d.push_back(flushed(n.fresnel * (l == 0 ? 1 - fresnel_share : fresnel_share)));
            }
        return d;
    }
};

namespace detail {

/// fit_two_lobes from `start`; where that fails, refitted from the node's one-lobe fit `one()` as
/// a single lobe (both lobes that fit, share 0) and the better of the two kept. Failed: an
/// implausible value (above 0.1: relative errors of the order of 0.3 and more); along a row, where
/// the grazing nodes' values reach 0.6 (theta_v near 90 deg), only if Nelder-Mead also stalled on
/// its first simplex or found no admissible point (a plateau of the objective). The failures this
/// guards against (tests/test_two_lobe.cpp), and the refits tried instead: docs/design_notes.md.
template <template <typename> class Brdf, typename OneLobe>
two_lobe_result fit_two_lobes_guarded(double cos_theta, double alpha, const two_lobe_start& start, const options& opt,
                                      bool along_row, OneLobe&& one) {
    constexpr double implausible = 0.1;
    two_lobe_result r = fit_two_lobes<Brdf>(cos_theta, alpha, start, opt);
    if (r.value <= implausible || (along_row && !r.stalled && std::isfinite(r.value))) return r;
    const ltc_parameters lobe = one();
    two_lobe_start single = start;
    single.lobes = {lobe, lobe};
    single.share = start.model == two_lobe_model::ltc_and_cosine ? 1.0 : 0.0;  // the LTC alone
    two_lobe_result again = fit_two_lobes<Brdf>(cos_theta, alpha, single, opt);
    const int evaluations = r.evaluations + again.evaluations;
    two_lobe_result& kept = again.value < r.value ? again : r;
    kept.evaluations = evaluations;
    return kept;
}

}  // namespace detail

/// Fits a two-lobe table: the normal-incidence nodes in sequence from roughness 1 down to 0 (the
/// first from the one-lobe fit of its node, each next from the previous one, guarded by
/// detail::fit_two_lobes_guarded), then each row of constant roughness from its normal-incidence
/// node towards grazing, each node from its neighbour, on options::threads threads (the result
/// does not depend on it). One of them runs the chain while the others take the rows in the
/// chain's order, each as soon as its first node is fitted. That order also puts the cheap rows
/// last (roughness below 0.2), so that the threads finish together. With the ltc_and_cosine model,
/// every node starts from its own one-lobe fit (start_with_cosine) instead of its neighbour's
/// two-lobe fit.
///
/// Progress: as fit_table's, `progress` (if set) is called on the calling thread, which waits for
/// the workers, about every options::progress_interval seconds and once at the end, with the
/// nodes fitted so far of size * size. If it throws, the workers stop after their current node of
/// the chain or their current row, and the exception is rethrown once they have joined.
///
/// Robustness: a lobe left with almost no share is dropped (fit_two_lobes), and the nodes that
/// land on a plateau of the objective are refitted from their one-lobe fit as a single lobe
/// (detail::fit_two_lobes_guarded): each fixed a failure of the table between the nodes of the
/// error report's grid (tests/test_two_lobe.cpp; tools/ggx_error_report --grid off). Caveat:
/// the fit stays fragile where the lobes' parts are not settled (roughness 0.2-0.25 at grazing
/// views), since nodes are marched from their neighbours and a table interpolates lobe by lobe
/// (tools/ggx_error_report, section 8).
template <template <typename> class Brdf>
two_lobe_table fit_two_lobe_table(const options& opt, two_lobe_model model = two_lobe_model::two_ltcs,
                                  const progress_callback& progress = {}) {
    if (opt.size < 2) throw std::invalid_argument("ltc::fit::fit_two_lobe_table: size must be at least 2");
    const int n = opt.size;
    two_lobe_table tab;
    tab.size = n;
    tab.model = model;
    tab.nodes.resize(std::size_t(n) * std::size_t(n));
    const std::size_t total = tab.nodes.size();
    const double c0 = node_cos_theta(0, n, opt.cos_theta_min);
    const std::vector<node_result> one0 = fit_normal_incidence<Brdf>(opt);  // the one-lobe fits, for starts
    const bool with_cosine = model == two_lobe_model::ltc_and_cosine;

    std::mutex mutex;
    std::condition_variable chain_advanced;
    int chain_at = n;  // the nodes (a, 0) with a >= chain_at are fitted
    bool stop = false;
    std::exception_ptr failure;
    std::atomic<int> next_row{n - 1};  // rows are taken downwards, in the chain's order
    std::atomic<std::size_t> done{0};  // nodes fitted
    const auto fail = [&] {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        stop = true;
        next_row.store(-1);
        chain_advanced.notify_all();
    };
    const auto fit_row = [&](int a) {
        two_lobe_result* row = &tab.nodes[std::size_t(a) * std::size_t(n)];
        const double alpha = node_alpha(a, n, opt.alpha_min);
        // The row's one-lobe fits, marched from normal incidence as fit_table does, as far as a
        // failed node needs them.
        node_result one_lobe = one0[std::size_t(a)];
        int one_lobe_at = 0;
        for (int t = 1; t < n; ++t) {
            const auto one = [&] {
                while (one_lobe_at < t) {
                    ++one_lobe_at;
                    one_lobe = fit_node<Brdf>(node_cos_theta(one_lobe_at, n, opt.cos_theta_min), alpha, one_lobe.parameters, opt);
                }
                return one_lobe.parameters;
            };
            const two_lobe_start start = with_cosine ? start_with_cosine(one()) : start_from(row[t - 1]);
            row[t] = detail::fit_two_lobes_guarded<Brdf>(node_cos_theta(t, n, opt.cos_theta_min), alpha, start, opt,
                                                         true, one);
            done.fetch_add(1);
        }
    };
    // The normal-incidence nodes, each released to the row workers once fitted.
    const auto chain = [&] {
        try {
            two_lobe_start start = start_from_one_lobe(one0[std::size_t(n - 1)].parameters);
            for (int a = n - 1; a >= 0; --a) {
                if (with_cosine) start = start_with_cosine(one0[std::size_t(a)].parameters);
                two_lobe_result& node = tab.nodes[std::size_t(a) * std::size_t(n)];
                node = detail::fit_two_lobes_guarded<Brdf>(c0, node_alpha(a, n, opt.alpha_min), start, opt, false,
                                                           [&] { return one0[std::size_t(a)].parameters; });
                start = start_from(node);
                done.fetch_add(1);
                std::lock_guard<std::mutex> lock(mutex);
                if (stop) break;
                chain_at = a;
                chain_advanced.notify_all();
            }
        } catch (...) {
            fail();
        }
    };
    const auto worker = [&] {
        try {
            for (int a; (a = next_row.fetch_sub(1)) >= 0;) {
                {
                    std::unique_lock<std::mutex> lock(mutex);
                    chain_advanced.wait(lock, [&] { return chain_at <= a || stop; });
                    if (stop) return;
                }
                fit_row(a);
            }
        } catch (...) {
            fail();
        }
    };
    const auto failed = [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return failure != nullptr;
    };
    // Thread 0 runs the chain before it takes rows too.
    const auto body = [&](unsigned i) {
        if (i == 0) chain();
        worker();
    };
    detail::run_fit_threads(opt, n, body, progress, done, total, fail, failed);
    if (failure) std::rethrow_exception(failure);
    return tab;
}

}  // namespace fit
LTC_NAMESPACE_END
