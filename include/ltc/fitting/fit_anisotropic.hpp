// ltc/fitting/fit_anisotropic.hpp -- fitting a table of full-matrix LTCs to an anisotropic BRDF
// over (alpha_x, alpha_y, theta_v, phi_v) (fit_anisotropic_table, on std::threads), one node
// (fit_anisotropic_node), the BRDF's moments (compute_anisotropic_moments) and the L3 objective
// (anisotropic_sample_set), after Kt, Heitz, Dupuy and Narayanan 2022, "Bringing Linearly
// Transformed Cosines to Anisotropic GGX", with the objective and minimizer of the isotropic fit.
//
//   const auto tab = ltc::fit::fit_anisotropic_table<ltc::brdf::ggx_anisotropic>(
//       ltc::fit::anisotropic_options{});
//   std::vector<float> data = tab.packed();   // the layout of ltc/tables/anisotropic_table.hpp
#pragma once

#include <ltc/config.hpp>

#include <ltc/brdf/ggx_anisotropic.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/fitting/anisotropic_parameters.hpp>
#include <ltc/fitting/fit_table.hpp>  // progress_callback, detail::run_fit_threads
#include <ltc/fitting/integral_objective.hpp>
#include <ltc/fitting/ltc_parameters.hpp>  // normalize_or_zero, sample_cosine
#include <ltc/fitting/error_metric.hpp>  // sample_set
#include <ltc/fitting/moments.hpp>
#include <ltc/fitting/nelder_mead.hpp>
#include <ltc/fitting/options.hpp>
#include <ltc/tables/anisotropic_table.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

// Per node (V = (sin t cos p, sin t sin p, cos t), alpha = {alpha_x, alpha_y}, frame N = +z,
// tangent +x): magnitude and fresnel as ltc/fitting/moments.hpp (midpoint rule through the BRDF's
// sampler), the average direction of f = rho cos without its y zeroed; then options::rounds rounds
// of Nelder-Mead (ltc/fitting/nelder_mead.hpp) on the paper's L3 distance
//
//   E(M) = integral |f(L) - magnitude D_M(L)|^3 dL ~= sum_i |f - m D|^3 / (n^2 p_brdf + n^2 p_ltc)
//
// over a frozen MIS sample set re-centred each round (ltc/fitting/error_metric.hpp's estimator
// for a full m_inv), in the parameters of ltc/fitting/anisotropic_parameters.hpp:
//   general node          7: (log m11, log m22, m12 / m22, m13 / m11, m23 / m22, m31, m32)
//   phi_v = 0 (mirror y)  4: (log m11, log m22, m13 / m11, m31), the isotropic fitter's matrix
//   phi_v = pi/2          the phi_v = 0 fit of the swapped BRDF (alpha_y, alpha_x), swapped back
//   theta_v = 0           2: diag(m11, m22, 1), 1 when alpha_x == alpha_y
// so that the nodes on the mirror planes are exactly symmetric and the lookup's mirrors are
// continuous. The stored matrix is canonical_matrix(canonical_inverse(M^-1)).
//
// Order (continuation, as the isotropic fit_table): per alpha pair with alpha_x >= alpha_y the
// normal-incidence node first (from diag(alpha_x, alpha_y, 1)), then for each phi node a chain
// from theta_v = 0 to grazing, each node started from its neighbour. Pairs with alpha_x <
// alpha_y are the swap symmetry's (ltc/tables/anisotropic_table.hpp), and so are the diagonal's
// nodes past phi = pi/4. Chains are independent work items: the result does not depend on the
// thread count. A node whose relative L1 error exceeds 1 is refitted from a fresh start (an
// isotropic lobe of width max(alpha_x, alpha_y) on the average direction) and the better kept.
//
// Thin nodes (j = 0 < i: alpha_y = alpha_min, a lobe that is almost a curve) come after all the
// other chains, each started from node (i, 1, k, l) and fitted for the table's interpolation
// (detail::anisotropic_fit_thin): its own objective, the objectives of the lobes a quarter and
// three quarters of the way to (i, 1, k, l) under the matrices that the lookup interpolates
// there, and a pull towards the linear extrapolation 2 M(i,1) - M(i,2). The
// node's own L3 distance is nearly flat there and its minimum a sheared matrix far from the
// neighbours, and the lobes between the two nodes, not the degenerate one, are what a shader sees.
//
// Degenerate cases: alpha below options::alpha_min is clamped (node 0 of each alpha axis);
// theta_v stops at theta_max = 0.9999 pi/2 (V.z = 0 leaves rho undefined); with an odd size the
// diagonal's middle phi node (phi = pi/4) is fitted without the swap constraint.

LTC_NAMESPACE_BEGIN
namespace fit {

using anisotropic_alpha = brdf::anisotropic_alpha<double>;

/// The anisotropic fitter's settings (the isotropic options' meanings; size nodes per axis).
struct anisotropic_options {
    int size = 8;                   ///< n: n^4 nodes (the published table's 8)
    double alpha_min = anisotropic_layout::alpha_min;
    int moment_samples = 64;        ///< n x n samples for magnitude, fresnel, average direction
    int error_samples = 32;         ///< n x n samples per distribution for the L3 error
    int rounds = 2;                 ///< proposal refreshes per node
    double tolerance = 1e-5;        ///< Nelder-Mead relative tolerance on the objective
    int max_evaluations = 1500;     ///< per Nelder-Mead run
    double initial_step = 0.1;      ///< simplex size of the first round
    unsigned threads = 0;           ///< worker threads (0: all cores)
    double progress_interval = 0.1; ///< seconds between progress callbacks
    objective goal = objective::combined;  ///< l3, integrals (anisotropic_polygon_family) or their sum
    double integral_floor = 0.01;    ///< the integral loss's floor, a fraction of the magnitude
    double l3_weight = 1.0;          ///< combined: integral loss + l3_weight * (relative L3)^2
};

/// alpha of node i of n: max(i / (n - 1), alpha_min).
inline double anisotropic_node_alpha(int i, int n, double alpha_min) {
    return std::max(n > 1 ? double(i) / double(n - 1) : 1.0, alpha_min);
}
/// theta_v of node k of n: k / (n - 1) theta_max.
inline double anisotropic_node_theta(int k, int n) {
    return n > 1 ? double(k) / double(n - 1) * anisotropic_layout::theta_max : 0.0;
}
/// phi_v of node l of n: l / (n - 1) pi / 2.
inline double anisotropic_node_phi(int l, int n) {
    return n > 1 ? double(l) / double(n - 1) * (0.5 * pi<double>()) : 0.0;
}
/// V at node (k, l): exactly in the xz-plane at l = 0, the yz-plane at l = n - 1, +z at k = 0.
inline glm::dvec3 anisotropic_node_view(int k, int l, int n) {
    if (k == 0) return glm::dvec3(0, 0, 1);
    const double t = anisotropic_node_theta(k, n), s = std::sin(t), c = std::cos(t);
    if (l == 0) return glm::dvec3(s, 0, c);
    if (l == n - 1) return glm::dvec3(0, s, c);
    const double p = anisotropic_node_phi(l, n);
    return glm::dvec3(s * std::cos(p), s * std::sin(p), c);
}

/// The moments of ltc/fitting/moments.hpp; the average direction keeps its y.
using anisotropic_moments = moments;

/// ltc/fitting/moments.hpp's quadrature for an alpha of any type, the average direction in 3D.
template <template <typename> class Brdf>
anisotropic_moments compute_anisotropic_moments(const glm::dvec3& V, const anisotropic_alpha& alpha, int n) {
    return detail::moments_by_quadrature<Brdf>(V, alpha, n, true);
}

/// error_metric.hpp's frozen MIS sample set (its overloads for a full m_inv).
using anisotropic_sample_set = sample_set;

/// n x n midpoints through the BRDF's sampler and n x n through the LTC of M, weights
/// 1 / (n^2 p_brdf + n^2 p_ltc) (error_metric.hpp's make_sample_set).
template <template <typename> class Brdf>
void make_anisotropic_sample_set(const glm::dvec3& V, const anisotropic_alpha& alpha, const glm::dmat3& M, int n,
                                 anisotropic_sample_set& out) {
    using B = Brdf<double>;
    const full_inverse_result inv = full_inverse(M);
    const double abs_det_inv = 1.0 / inv.abs_determinant;
    const double count = double(n) * double(n);
    out.clear();
    const auto add = [&](const glm::dvec3& L) {
        const double f = L.z > 0 ? B::eval(V, L, alpha) : 0.0;
        const double p = count * (B::pdf(V, L, alpha) + ltc_density(inv.inverse, abs_det_inv, L));
        if (p > 0 && std::isfinite(p) && std::isfinite(f)) out.add(L, f, 1.0 / p);
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 u((i + 0.5) / n, (j + 0.5) / n);
            add(B::sample(V, u, alpha));
            add(normalize_or_zero(M * sample_cosine(u)));
        }
}

/// Which parameters a node frees (the file comment).
enum class node_symmetry { general, mirror_y, normal };

struct anisotropic_node {
    anisotropic_parameters parameters;  ///< the fit (in the swapped frame for a phi = pi/2 chain)
    glm::dmat3 m_inv{1.0};              ///< canonical_inverse(M^-1)
    glm::dmat3 matrix{1.0};             ///< the stored matrix: m_inv^-1 / |m_inv^-1 e_z|
    double magnitude = 0;               ///< integral of rho cos
    double fresnel = 0;                 ///< integral of rho cos (1 - V.H)^5
    double relative_l1 = 0;             ///< integral |f - m D| / integral f (the fit's estimator)
    double relative_l3 = 0;             ///< (integral |f - m D|^3 / integral f^3)^(1/3)
    int evaluations = 0;
};

namespace detail {

inline int anisotropic_dims(node_symmetry s, bool equal_alphas) {
    return s == node_symmetry::general ? 7 : s == node_symmetry::mirror_y ? 4 : (equal_alphas ? 1 : 2);
}

inline anisotropic_parameters anisotropic_from_vector(const double* u, int dims, const glm::dvec3& axis) {
    anisotropic_parameters p;
    p.axis = axis;
    p.m11 = std::exp(u[0]);
    p.m22 = dims == 1 ? p.m11 : std::exp(u[1]);
    if (dims == 4) {
        p.m13 = u[2] * p.m11;
        p.m31 = u[3];
    } else if (dims == 7) {
        p.m12 = u[2] * p.m22;
        p.m13 = u[3] * p.m11;
        p.m23 = u[4] * p.m22;
        p.m31 = u[5];
        p.m32 = u[6];
    }
    return p;
}

inline void anisotropic_to_vector(const anisotropic_parameters& p, int dims, double* u) {
    u[0] = std::log(p.m11);
    if (dims == 1) return;
    u[1] = std::log(p.m22);
    if (dims == 4) {
        u[2] = p.m13 / p.m11;
        u[3] = p.m31;
    } else if (dims == 7) {
        u[2] = p.m12 / p.m22;
        u[3] = p.m13 / p.m11;
        u[4] = p.m23 / p.m22;
        u[5] = p.m31;
        u[6] = p.m32;
    }
}

template <std::size_t Dim, typename Objective>
anisotropic_parameters anisotropic_minimize(const Objective& objective_of, const anisotropic_parameters& start, double step,
                                            const anisotropic_options& opt, int& evaluations) {
    constexpr int dims = int(Dim);
    std::array<double, Dim> u0{}, steps{};
    anisotropic_to_vector(start, dims, u0.data());
    steps.fill(step);
    const auto objective = [&](const std::array<double, Dim>& u) {
        const anisotropic_parameters p = anisotropic_from_vector(u.data(), dims, start.axis);
        if (!(p.m11 > 0) || !(p.m22 > 0) || !std::isfinite(p.m11) || !std::isfinite(p.m22) ||
            !(glm::determinant(p.block()) > 0))
            return std::numeric_limits<double>::infinity();
        const full_inverse_result inv = full_inverse(p.matrix());
        if (!inv.ok) return std::numeric_limits<double>::infinity();
        return objective_of(inv.inverse, 1.0 / inv.abs_determinant);
    };
    const auto r = nelder_mead<Dim>(objective, u0, steps, opt.tolerance, opt.max_evaluations);
    evaluations += r.evaluations;
    return anisotropic_from_vector(r.x.data(), dims, start.axis);
}

/// anisotropic_minimize over the node's free parameters (dims: 7, 4, 2 or 1, its symmetry's).
template <typename Objective>
anisotropic_parameters anisotropic_minimize(int dims, const Objective& objective_of, const anisotropic_parameters& start,
                                            double step, const anisotropic_options& opt, int& evaluations) {
    if (dims == 7) return anisotropic_minimize<7>(objective_of, start, step, opt, evaluations);
    if (dims == 4) return anisotropic_minimize<4>(objective_of, start, step, opt, evaluations);
    if (dims == 2) return anisotropic_minimize<2>(objective_of, start, step, opt, evaluations);
    return anisotropic_minimize<1>(objective_of, start, step, opt, evaluations);
}

/// The integral objective's polygons for a lobe of average direction `axis` (unit, 3D) and
/// roughness alpha: integral_objective.hpp's families without the y symmetry.
///   lobe       radii r_j = r0 (1.2 / r0)^(j / 4), j = 0..4, r0 = clamp(0.35 (alpha_x + alpha_y),
///              5e-5, 0.3), centred on the axis, and for j < 4 also 2 r_j away from it towards
///              the normal, the horizon and both sides: 5 + 16 hexagons;
///   hemisphere radius 0.25 rad at elevations 8, 30 and 55 deg, azimuths 22.5 + 45 k deg
///              (k = 0..7), and at elevation 85 deg; radius 0.6 rad at elevations 15 and 50
///              deg, azimuths 60 k deg: 37 hexagons (the lowest ring straddles the horizon).
inline std::vector<family_polygon> anisotropic_polygon_family(const glm::dvec3& axis, const anisotropic_alpha& alpha) {
    std::vector<family_polygon> family;
    const double r0 = std::min(std::max(0.35 * (alpha.x + alpha.y), 5e-5), 0.3);
    // The frame of the axis: `up` towards the normal, `side` across (a horizontal tangent).
    const glm::dvec3 h(axis.x, axis.y, 0);
    const glm::dvec3 side = glm::dot(h, h) > 1e-24 ? normalize_or_zero(glm::dvec3(-axis.y, axis.x, 0)) : glm::dvec3(0, 1, 0);
    const glm::dvec3 up = glm::cross(side, axis);  // towards +z (or +x... at normal incidence)
    const auto off_axis = [&](double d, double az) {
        const glm::dvec3 dir = std::cos(az) * up + std::sin(az) * side;
        return normalize_or_zero(axis * std::cos(d) + dir * std::sin(d));
    };
    for (int j = 0; j < 5; ++j) {
        const double r = r0 * std::pow(1.2 / r0, j / 4.0);
        family.push_back(make_hexagon(axis, r));
        if (j == 4) break;
        for (int q = 0; q < 4; ++q) family.push_back(make_hexagon(off_axis(2 * r, 0.5 * pi<double>() * q), r));
    }
    const auto at = [](double el_deg, double az_deg) {
        const double e = el_deg * pi<double>() / 180.0, a = az_deg * pi<double>() / 180.0;
        return glm::dvec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
    };
    for (double el : {8.0, 30.0, 55.0})
        for (int k = 0; k < 8; ++k) family.push_back(make_hexagon(at(el, 22.5 + 45.0 * k), 0.25));
    family.push_back(make_hexagon(at(85.0, 22.5), 0.25));
    for (double el : {15.0, 50.0})
        for (int k = 0; k < 6; ++k) family.push_back(make_hexagon(at(el, 60.0 * k), 0.6));
    return family;
}

/// One lobe's objective (options::goal) on a sample set re-centred on a given matrix (refresh).
struct anisotropic_objective {
    glm::dvec3 V;
    anisotropic_alpha alpha;
    double magnitude = 0;
    const anisotropic_options* opt = nullptr;
    anisotropic_sample_set samples;
    integral_targets targets;
    double f3 = 1;

    template <template <typename> class Brdf>
    void init(const glm::dvec3& v, const anisotropic_alpha& a, const anisotropic_moments& mom, const glm::dvec3& axis,
              const anisotropic_options& o) {
        V = v;
        alpha = a;
        magnitude = mom.magnitude;
        opt = &o;
        if (o.goal != objective::l3) {
            const std::vector<family_polygon> family = anisotropic_polygon_family(axis, a);
            std::vector<double> g;
            family_integrals<Brdf>(V, a, family, default_brdf_samples, default_polygon_samples, g, nullptr);
            targets = significant_targets(family, g, mom.magnitude, o.integral_floor);
        }
    }
    template <template <typename> class Brdf>
    void refresh(const glm::dmat3& M) {
        make_anisotropic_sample_set<Brdf>(V, alpha, M, opt->error_samples, samples);
        f3 = 1;
        if (opt->goal == objective::combined) {
            const full_inverse_result inv = full_inverse(M);
            f3 = samples.all(inv.inverse, 1.0 / inv.abs_determinant, magnitude).f3;
            if (!(f3 > 0)) f3 = 1;
        }
    }
    double operator()(const glm::dmat3& m_inv, double abs_det) const {
        if (opt->goal == objective::l3) return samples.l3(m_inv, abs_det, magnitude);
        double e = integral_loss(targets, m_inv, magnitude);
        if (opt->goal == objective::combined) {
            const double l3 = std::cbrt(samples.l3(m_inv, abs_det, magnitude) / f3);
            e += opt->l3_weight * l3 * l3;
        }
        return e;
    }
};

/// r's matrices and errors from the fitted parameters p, the errors on `samples`.
inline void finish_node(anisotropic_node& r, const anisotropic_parameters& p, const anisotropic_sample_set& samples) {
    r.parameters = p;
    const full_inverse_result inv = full_inverse(p.matrix());
    r.m_inv = canonical_inverse(inv.inverse);
    r.matrix = canonical_matrix(r.m_inv);
    const auto s = samples.all(inv.inverse, 1.0 / inv.abs_determinant, r.magnitude);
    r.relative_l1 = s.f1 > 0 ? s.l1 / s.f1 : 0.0;
    r.relative_l3 = s.f3 > 0 ? std::cbrt(s.l3 / s.f3) : 0.0;
}

template <template <typename> class Brdf>
anisotropic_node anisotropic_fit_from(const glm::dvec3& V, const anisotropic_alpha& alpha,
                                      const anisotropic_moments& mom, int dims, anisotropic_parameters p,
                                      const anisotropic_options& opt) {
    anisotropic_node r;
    r.magnitude = mom.magnitude;
    r.fresnel = mom.fresnel;
    anisotropic_objective objective;
    objective.init<Brdf>(V, alpha, mom, p.axis, opt);
    double step = opt.initial_step;
    for (int round = 0; round < std::max(1, opt.rounds); ++round) {
        objective.refresh<Brdf>(p.matrix());
        p = anisotropic_minimize(dims, objective, p, step, opt, r.evaluations);
        step *= 0.25;
    }
    finish_node(r, p, objective.samples);
    return r;
}

/// A thin node (one alpha at alpha_min, the other not: the lobe almost a curve), after the file
/// comment: the node's objective, plus that of the lobes a quarter and three quarters of the way
/// to the neighbour node (alpha_far) under the matrices that the table interpolates there (from
/// the canonical matrices; `neighbour` canonical, in the node's frame): the midpoint rule for the
/// interpolated lobes' error; plus a pull, reference_weight times the squared distance of the
/// canonical matrix to `reference` (the linear extrapolation of the two neighbours). The L3
/// distance alone is nearly flat in the thin direction, and its minimum there a sheared matrix
/// that the table cannot interpolate to the neighbours.
template <template <typename> class Brdf>
anisotropic_node anisotropic_fit_thin(const glm::dvec3& V, const anisotropic_alpha& alpha,
                                      const anisotropic_alpha& alpha_far, const anisotropic_moments& mom, int dims,
                                      anisotropic_parameters p, const glm::dmat3& neighbour,
                                      const glm::dmat3& reference, const anisotropic_options& opt) {
    anisotropic_node r;
    r.magnitude = mom.magnitude;
    r.fresnel = mom.fresnel;
    constexpr int between = 2;
    // Strong, so that mainly the objective's flat directions follow it; a weaker pull leaves the
    // wide axis of a thin lobe narrower than the neighbours' (tools/anisotropic_error_report).
    const double reference_weight = 100.0;
    const auto position = [](int b) { return (double(b) + 0.5) / double(between); };  // t in (0, 1)
    anisotropic_objective node_objective, mid_objective[between];
    node_objective.init<Brdf>(V, alpha, mom, p.axis, opt);
    for (int b = 0; b < between; ++b) {
        const double t = position(b);
        const anisotropic_alpha a{alpha.x + t * (alpha_far.x - alpha.x), alpha.y + t * (alpha_far.y - alpha.y)};
        mid_objective[b].init<Brdf>(V, a, compute_anisotropic_moments<Brdf>(V, a, opt.moment_samples), p.axis, opt);
    }
    const auto canonical = [](const glm::dmat3& m_inv) { return canonical_matrix(canonical_inverse(m_inv)); };
    const auto between_matrix = [&](const glm::dmat3& c, int b) { return (1 - position(b)) * c + position(b) * neighbour; };
    double step = opt.initial_step;
    for (int round = 0; round < std::max(1, opt.rounds); ++round) {
        node_objective.refresh<Brdf>(p.matrix());
        const glm::dmat3 c0 = canonical(full_inverse(p.matrix()).inverse);
        for (int b = 0; b < between; ++b) mid_objective[b].refresh<Brdf>(between_matrix(c0, b));
        const auto objective_of = [&](const glm::dmat3& m_inv, double abs_det) {
            const glm::dmat3 c = canonical(m_inv);
            const glm::dmat3 d = c - reference;
            double e = node_objective(m_inv, abs_det);
            for (int k = 0; k < 3; ++k) e += reference_weight * glm::dot(d[k], d[k]);
            for (int b = 0; b < between; ++b) {
                const full_inverse_result mid = full_inverse(between_matrix(c, b));
                if (!mid.ok) return std::numeric_limits<double>::infinity();
                e += mid_objective[b](mid.inverse, 1.0 / mid.abs_determinant);
            }
            return e;
        };
        p = anisotropic_minimize(dims, objective_of, p, step, opt, r.evaluations);
        step *= 0.25;
    }
    finish_node(r, p, node_objective.samples);
    return r;
}

/// The parameters of the LTC of M about `axis` (M's LTC, up to M -> s M Q, s > 0, Q a rotation
/// about z or a mirror: anisotropic_parameters.hpp): B = R(axis)^T M Q / s with B[1][0] = 0,
/// m11, m22 > 0 and B[2][2] = 1. False (p unchanged) where no such B exists.
inline bool parameters_from_matrix(const glm::dmat3& M, const glm::dvec3& axis, anisotropic_parameters& p) {
    const glm::dmat3 B = glm::transpose(rotation_to(axis)) * M;  // B[column][row]
    const double b10 = B[0][1], b11 = B[1][1];
    const double r = std::sqrt(b10 * b10 + b11 * b11);
    if (!(r > 0) || !std::isfinite(r)) return false;
    const double c = b11 / r, s = -b10 / r;  // Q e_x = (c, s, 0), Q e_y = (-s, c, 0)
    glm::dvec3 c0 = c * B[0] + s * B[1];
    const glm::dvec3 c1 = -s * B[0] + c * B[1];
    const glm::dvec3 c2 = B[2];
    if (c0.x < 0) c0 = -c0;  // the mirror x -> -x
    if (!(c2.z > 0) || !(c0.x > 0) || !(c1.y > 0)) return false;
    const double k = 1.0 / c2.z;
    anisotropic_parameters q;
    q.axis = axis;
    q.m11 = c0.x * k;
    q.m31 = c0.z * k;
    q.m12 = c1.x * k;
    q.m22 = c1.y * k;
    q.m32 = c1.z * k;
    q.m13 = c2.x * k;
    q.m23 = c2.y * k;
    // The fit's domain (anisotropic_minimize): the mirror above can leave det B <= 0.
    if (!std::isfinite(q.m11 + q.m22 + q.m12 + q.m13 + q.m23 + q.m31 + q.m32) || !(glm::determinant(q.block()) > 0))
        return false;
    p = q;
    return true;
}

}  // namespace detail

/// A thin node's neighbour (detail::anisotropic_fit_thin): the roughness halfway to it and its
/// canonical matrix in the node's frame.
struct anisotropic_thin {
    anisotropic_alpha alpha_far;
    glm::dmat3 neighbour{1.0};
    glm::dmat3 reference{1.0};
};

/// Fits one node: view V (unit, V.z > 0), roughness alpha, the parameters that `symmetry` frees,
/// starting from `start` (its axis replaced by the BRDF's average direction; with mirror_y, V.y
/// must be 0 and the axis's y is zeroed; with normal, V = +z and the axis is +z), or from the LTC
/// of `start_matrix` where given (detail::parameters_from_matrix about that axis). With `thin`,
/// the thin node's fit (detail::anisotropic_fit_thin, no safeguard: its pull keeps it near the
/// neighbours). See the file comment for the safeguard.
template <template <typename> class Brdf>
anisotropic_node fit_anisotropic_node(const glm::dvec3& V, const anisotropic_alpha& alpha, node_symmetry symmetry,
                                      const anisotropic_parameters& start, const anisotropic_options& opt,
                                      const glm::dmat3* start_matrix = nullptr,
                                      const anisotropic_thin* thin = nullptr) {
    const anisotropic_moments mom = compute_anisotropic_moments<Brdf>(V, alpha, opt.moment_samples);
    const bool equal = alpha.x == alpha.y;
    const int dims = detail::anisotropic_dims(symmetry, equal);
    anisotropic_parameters p = start;
    p.axis = mom.average_direction;
    if (start_matrix) {
        glm::dvec3 axis = p.axis;
        if (symmetry == node_symmetry::mirror_y) axis = normalize_or_zero(glm::dvec3(axis.x, 0, axis.z));
        if (axis.z > 0) detail::parameters_from_matrix(*start_matrix, axis, p);
        p.axis = mom.average_direction;
    }
    if (symmetry == node_symmetry::mirror_y) {
        p.axis.y = 0;
        p.axis = normalize_or_zero(p.axis);
        p.m12 = p.m23 = p.m32 = 0;
    } else if (symmetry == node_symmetry::normal) {
        p.axis = glm::dvec3(0, 0, 1);
        p.m12 = p.m13 = p.m23 = p.m31 = p.m32 = 0;
        if (equal) p.m22 = p.m11;
    }
    if (!(p.axis.z > 0)) p.axis = glm::dvec3(0, 0, 1);
    if (thin) return detail::anisotropic_fit_thin<Brdf>(V, alpha, thin->alpha_far, mom, dims, p, thin->neighbour, thin->reference, opt);
    anisotropic_node r = detail::anisotropic_fit_from<Brdf>(V, alpha, mom, dims, p, opt);
    if (!(r.relative_l1 <= 1.0)) {
        anisotropic_parameters fresh;
        fresh.axis = p.axis;
        fresh.m11 = fresh.m22 = std::min(std::max(std::max(alpha.x, alpha.y), 1e-6), 1.0);
        anisotropic_node alt = detail::anisotropic_fit_from<Brdf>(V, alpha, mom, dims, fresh, opt);
        alt.evaluations += r.evaluations;
        if (alt.relative_l1 < r.relative_l1 || !(r.relative_l1 == r.relative_l1)) r = alt;
        else r.evaluations = alt.evaluations;
    }
    if (opt.goal != objective::l3 && !(r.relative_l1 <= 1.0)) {
        // A lobe that the integral objective barely constrains: the L3 fit instead (fit_node.hpp).
        anisotropic_options l3 = opt;
        l3.goal = objective::l3;
        anisotropic_node alt = detail::anisotropic_fit_from<Brdf>(V, alpha, mom, dims, p, l3);
        alt.evaluations += r.evaluations;
        r = alt;
    }
    return r;
}

/// A fitted table: the stored nodes (alpha pairs i >= j) in the order of
/// ltc/tables/anisotropic_table.hpp, nodes[(pair_index(i, j) * n + k) * n + l].
struct anisotropic_table_fit {
    int size = 0;
    std::vector<anisotropic_node> nodes;

    const anisotropic_node& at(int i, int j, int k, int l) const {
        return nodes[(anisotropic_layout::pair_index(i, j) * std::size_t(size) + std::size_t(k)) * std::size_t(size) +
                     std::size_t(l)];
    }
    anisotropic_node& at(int i, int j, int k, int l) {
        return nodes[(anisotropic_layout::pair_index(i, j) * std::size_t(size) + std::size_t(k)) * std::size_t(size) +
                     std::size_t(l)];
    }

    /// The floats of ltc/tables/anisotropic_table.hpp (11 per node).
    std::vector<float> packed() const {
        std::vector<float> d;
        d.reserve(nodes.size() * anisotropic_layout::channels);
        for (const anisotropic_node& n : nodes) {
            for (int c = 0; c < 3; ++c)
                for (int w = 0; w < 3; ++w) d.push_back(float(n.matrix[c][w]));
            d.push_back(float(n.magnitude));
            d.push_back(float(n.fresnel));
        }
        return d;
    }
};

namespace detail {

/// node with x and y swapped (the swap symmetry): S m_inv S, m11 <-> m22 etc. of the parameters
/// are not needed (only the start of a chain is swapped: swap_start).
inline anisotropic_node swapped(anisotropic_node n) {
    n.m_inv = ltc::detail::swap_xy(n.m_inv);
    n.matrix = ltc::detail::swap_xy(n.matrix);
    return n;
}

/// The normal-incidence parameters in the swapped frame (diagonal: m11 <-> m22).
inline anisotropic_parameters swap_start(anisotropic_parameters p) {
    std::swap(p.m11, p.m22);
    return p;
}

}  // namespace detail

/// Fits the n^4 table (the file comment) on options::threads threads.
template <template <typename> class Brdf>
anisotropic_table_fit fit_anisotropic_table(const anisotropic_options& opt, const progress_callback& progress = {}) {
    if (opt.size < 2) throw std::invalid_argument("ltc::fit::fit_anisotropic_table: size must be at least 2");
    const int n = opt.size;
    anisotropic_table_fit tab;
    tab.size = n;
    const std::size_t pairs = anisotropic_layout::pair_index(n, 0);
    tab.nodes.resize(pairs * std::size_t(n) * std::size_t(n));
    const auto alpha_of = [&](int i, int j) {
        return anisotropic_alpha{anisotropic_node_alpha(i, n, opt.alpha_min), anisotropic_node_alpha(j, n, opt.alpha_min)};
    };

    // Phase 1, sequential: the normal-incidence node of each pair (one or two parameters, cheap).
    std::vector<anisotropic_node> normal(pairs);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j <= i; ++j) {
            const anisotropic_alpha a = alpha_of(i, j);
            anisotropic_parameters start;
            start.m11 = a.x;
            start.m22 = a.y;
            normal[anisotropic_layout::pair_index(i, j)] =
                fit_anisotropic_node<Brdf>(glm::dvec3(0, 0, 1), a, node_symmetry::normal, start, opt);
        }

    // Phase 2: the chains (pair, l) along theta, in parallel.
    struct chain {
        int i, j, l;
    };
    std::vector<chain> chains, thin_chains;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j <= i; ++j)
            for (int l = 0; l < (i == j ? (n + 1) / 2 : n); ++l)
                (j == 0 && i > 0 && n > 2 ? thin_chains : chains).push_back(chain{i, j, l});
    const std::size_t total = (chains.size() + thin_chains.size()) * std::size_t(n - 1);

    std::atomic<std::size_t> done{0};
    std::atomic<std::size_t> next{0};
    std::mutex mutex;
    std::exception_ptr failure;
    const auto fail = [&] {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        next.store(chains.size() + thin_chains.size());
    };
    const auto failed = [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return failure != nullptr;
    };
    const std::vector<chain>* work = &chains;
    const auto worker = [&](unsigned) {
        try {
            for (;;) {
                const std::size_t c = next.fetch_add(1);
                if (c >= work->size()) break;
                const chain ch = (*work)[c];
                const anisotropic_node& nn = normal[anisotropic_layout::pair_index(ch.i, ch.j)];
                tab.at(ch.i, ch.j, 0, ch.l) = nn;
                // phi = pi/2 (off the diagonal): the phi = 0 chain of the swapped BRDF.
                const bool swap = ch.l == n - 1 && ch.i != ch.j;
                const anisotropic_alpha a = swap ? alpha_of(ch.j, ch.i) : alpha_of(ch.i, ch.j);
                const node_symmetry sym = (ch.l == 0 || swap) ? node_symmetry::mirror_y : node_symmetry::general;
                anisotropic_parameters p = swap ? detail::swap_start(nn.parameters) : nn.parameters;
                for (int k = 1; k < n; ++k) {
                    const glm::dvec3 V = anisotropic_node_view(k, swap ? 0 : ch.l, n);
                    anisotropic_node r;
                    if (ch.j == 0 && ch.i > 0 && n > 2) {
                        // A thin lobe: continuation in alpha_y from the fitted node (i, 1, k, l).
                        const anisotropic_node& ref = tab.at(ch.i, 1, k, ch.l);
                        anisotropic_thin thin;
                        thin.neighbour = swap ? ltc::detail::swap_xy(ref.matrix) : ref.matrix;
                        const glm::dmat3 far = ch.i >= 2 ? tab.at(ch.i, 2, k, ch.l).matrix
                                                         : ltc::detail::swap_xy(tab.at(2, ch.i, k, n - 1 - ch.l).matrix);
                        thin.reference = 2.0 * thin.neighbour - (swap ? ltc::detail::swap_xy(far) : far);
                        const double t = anisotropic_node_alpha(1, n, opt.alpha_min);
                        thin.alpha_far = swap ? anisotropic_alpha{t, a.y} : anisotropic_alpha{a.x, t};
                        r = fit_anisotropic_node<Brdf>(V, a, sym, p, opt, &thin.neighbour, &thin);
                    } else {
                        r = fit_anisotropic_node<Brdf>(V, a, sym, p, opt);
                    }
                    p = r.parameters;
                    tab.at(ch.i, ch.j, k, ch.l) = swap ? detail::swapped(r) : r;
                    done.fetch_add(1);
                }
            }
        } catch (...) {
            fail();
        }
    };
    options threads;
    threads.threads = opt.threads;
    threads.progress_interval = opt.progress_interval;
    detail::run_fit_threads(threads, int(chains.size()), worker, progress, done, total, fail, failed);
    if (failure) std::rethrow_exception(failure);

    // The diagonal past phi = pi/4: the swap of phi -> pi/2 - phi.
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < n; ++k)
            for (int l = (n + 1) / 2; l < n; ++l) tab.at(i, i, k, l) = detail::swapped(tab.at(i, i, k, n - 1 - l));

    if (!thin_chains.empty()) {
        work = &thin_chains;
        next.store(0);
        detail::run_fit_threads(threads, int(thin_chains.size()), worker, progress, done, total, fail, failed);
        if (failure) std::rethrow_exception(failure);
    }
    return tab;
}

/// Mean and maximum of the fit's relative L1 and L3 errors over the stored nodes.
struct anisotropic_error_summary {
    double mean_l1 = 0, max_l1 = 0, mean_l3 = 0, max_l3 = 0;
};

inline anisotropic_error_summary summarize_error(const anisotropic_table_fit& tab) {
    anisotropic_error_summary e;
    for (const auto& n : tab.nodes) {
        e.mean_l1 += n.relative_l1;
        e.mean_l3 += n.relative_l3;
        e.max_l1 = std::max(e.max_l1, n.relative_l1);
        e.max_l3 = std::max(e.max_l3, n.relative_l3);
    }
    if (!tab.nodes.empty()) {
        e.mean_l1 /= double(tab.nodes.size());
        e.mean_l3 /= double(tab.nodes.size());
    }
    return e;
}

/// The text of the generated header (ltc/tables/<name>.hpp): <name>_size and <name>_data in the
/// layout of ltc/tables/anisotropic_table.hpp, 9 significant digits per float (bit for bit), after
/// a comment recording the options and the fit error. A function of the table and options only.
inline std::string anisotropic_table_header_text(const std::string& name, const std::string& description,
                                                 const anisotropic_table_fit& tab, const anisotropic_options& opt) {
    const int n = tab.size;
    const anisotropic_error_summary err = summarize_error(tab);
    const auto literal = [](float v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.9g", double(v));
        std::string s = buf;
        if (s.find_first_of(".e") == std::string::npos) s += ".";
        return s + "f";
    };
    const auto num = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6g", v);
        return std::string(buf);
    };
    const auto num4 = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.4f", v);
        return std::string(buf);
    };
    std::ostringstream o;
    o << "// ltc/tables/" << name << ".hpp -- GENERATED by tools/ltc_fit.cpp; do not edit.\n"
      << "//\n"
      << "// Regenerate (from the repository root; the output does not depend on --threads):\n"
      << "//   cmake --build build --target ltc_fit && ./build/tools/ltc_fit --brdf " << name
      << " --out include/ltc/tables/" << name << ".hpp\n"
      << "//\n"
      << "// BRDF: " << description << ".\n"
      << "// Size: " << n << "^4 nodes over (alpha_x, alpha_y, theta_v, phi_v), the " << anisotropic_layout::pair_index(n, 0)
      << " alpha pairs with alpha_x >= alpha_y stored,\n"
      << "// 11 floats each; alpha = max(i / " << n - 1 << ", " << num(opt.alpha_min) << "), theta_v = k / " << n - 1
      << " * 0.9999 pi/2, phi_v = l / " << n - 1 << " * pi/2;\n"
      << "// data[((pair * " << n << " + k) * " << n << " + l) * 11 + channel], pair = i (i + 1) / 2 + j. Channels:\n"
      << "// M[c][r] at 3 c + r (GLM column-major) of the LTC matrix M (not its inverse) in canonical form\n"
      << "// (M^-1 with det > 0 and a symmetric upper-left 2x2 block of the largest trace, M scaled to |M e_z| = 1),\n"
      << "// magnitude = integral of rho cos, fresnel = integral of rho cos (1 - V.H)^5.\n"
      << "// Look it up with ltc::anisotropic_table (ltc/tables/anisotropic_table.hpp) or ltc::ggx_anisotropic::fetch.\n"
      << "// Fit (ltc/fitting/fit_anisotropic.hpp): M = R [m11 m12 m13; 0 m22 m23; m31 m32 1], R the rotation\n"
      << "// to the average direction, minimizing the L3 error (MIS over " << opt.error_samples << " x "
      << opt.error_samples << " BRDF and LTC samples,\n"
      << "// " << opt.rounds << " rounds, Nelder-Mead tolerance " << num(opt.tolerance) << "); moments over "
      << opt.moment_samples << " x " << opt.moment_samples << " samples.\n"
      << "// Fit error (relative to rho cos, as estimated by the fit): L1 mean " << num4(err.mean_l1) << ", max "
      << num4(err.max_l1) << "; L3 mean " << num4(err.mean_l3) << ", max " << num4(err.max_l3) << ".\n"
      << "#pragma once\n\n"
      << "namespace ltc {\nnamespace tables {\n\n"
      << "inline constexpr int " << name << "_size = " << n << ";\n\n"
      << "inline constexpr float " << name << "_data[" << anisotropic_layout::pair_index(n, 0) << " * " << n << " * "
      << n << " * 11] = {\n";
    const std::vector<float> d = tab.packed();
    for (int i = 0; i < n; ++i)
        for (int j = 0; j <= i; ++j) {
            o << "    // alpha pair (" << i << ", " << j << ")\n";
            for (int k = 0; k < n; ++k)
                for (int l = 0; l < n; ++l) {
                    const std::size_t base =
                        ((anisotropic_layout::pair_index(i, j) * std::size_t(n) + std::size_t(k)) * std::size_t(n) +
                         std::size_t(l)) *
                        anisotropic_layout::channels;
                    o << "   ";
                    for (int c = 0; c < anisotropic_layout::channels; ++c) o << " " << literal(d[base + std::size_t(c)]) << ",";
                    o << "\n";
                }
        }
    o << "};\n\n}  // namespace tables\n}  // namespace ltc\n";
    return o.str();
}

}  // namespace fit
LTC_NAMESPACE_END
