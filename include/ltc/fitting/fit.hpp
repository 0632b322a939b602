// ltc/fitting/fit.hpp -- fitting Linearly Transformed Cosines to a BRDF (paper section 4), and whole
// tables of them (the paper's 64 x 64 GGX table, or any BRDF model of ltc/fitting/brdf/model.hpp).
//
//   #include <ltc/fitting/fit.hpp>
//   #include <ltc/fitting/brdf/ggx.hpp>
//   ltc::fit::options opt;                                   // 64 x 64, all cores
//   ltc::fit::table tab = ltc::fit::fit_table<ltc::brdf::ggx>(opt);
//   std::vector<float> data = tab.packed();                  // the layout of ltc/shading/table.hpp
//   ltc::ltc_table view(data.data(), tab.size, tab.size);    // then view.fetch(cos, roughness)
//
// What is fitted. For a view direction V = (sin theta_v, 0, cos theta_v) (local frame N = +z)
// and a roughness alpha, the spherical function f(L) = rho(V, L) cos(theta_L) (Brdf::eval) is
// approximated by magnitude * D(L), D the linearly transformed cosine of a matrix
//
//   M = R * [m11 0 m13; 0 m22 0; m31 0 1]     (rows; GLM stores M[column][row])
//
// where R is the rotation about y that takes +z to the BRDF's average direction (the direction
// of the integral of f(L) L, y component zeroed). That is the paper's 4-parameter matrix
// [a 0 b; 0 c 0; d 0 1] written in the rotated frame: the general matrix of an isotropic BRDF
// up to scale. (The paper's code release keeps m31 = 0 and fits 3 parameters; options::
// parameters = 3 does the same.) At normal incidence the lobe is rotationally symmetric and
// M = diag(m, m, 1) has one parameter.
//
// Per-node quantities, all by deterministic quadrature (the midpoint rule on an n x n grid of
// u in [0, 1)^2 pushed through Brdf::sample, i.e. stratified importance sampling without random
// numbers; n = options::moment_samples):
//   magnitude = integral of f(L) dL                                  (directional albedo)
//   fresnel   = integral of f(L) (1 - V.H)^5 dL, H = (V + L)/|V + L| (Hill 2016: with Schlick's
//               F = F0 + (1 - F0)(1 - V.H)^5, integral of f F = F0 magnitude + (1 - F0) fresnel)
//   average direction = integral of f(L) L dL, y set to 0, normalized.
//
// Error metric: the paper's L3 distance
//
//   E(M) = integral over the sphere of |f(L) - magnitude * D_M(L)|^3 dL,
//
// estimated, like the paper's code, by multiple importance sampling with the balance heuristic
// over two n x n midpoint grids (n = options::error_samples): one through Brdf::sample, one
// through the LTC's own sampler (Algorithm 1): E ~= sum_i |f - m D|^3 / (n^2 p_brdf + n^2 p_ltc).
// One change, for speed and for a smooth objective: the LTC samples are drawn from a *frozen*
// proposal LTC (the starting point of the current round) instead of the current candidate, so
// that f, p_brdf and p_ltc are computed once per round and each evaluation of E only evaluates
// D_M (a 3x3 product and a division per sample, no BRDF call: ~10x faster per node than the
// paper's code). Like the paper's, this is an importance-sampling estimate of E for any
// candidate (MIS with a fixed proposal instead of a moving one); it is most accurate near the
// proposal, so the fit runs options::rounds rounds, each re-centring the proposal on the
// previous round's result, and the last round's proposal is close to the final LTC as in the
// paper. The frozen samples also make E a fixed smooth function of the parameters during a
// minimization, so that Nelder-Mead converges instead of chasing the noise of moving samples.
// Why L3 and not, say, L1 or L2: the paper found that it gives the best visual results (it
// weighs the peak of the lobe, where highlights come from, more than the tails); we keep it and
// report the result in both L1 and L3 (node_result, measure_error).
//
// Minimizer: Nelder-Mead (Lagarias et al. 1998 variant, standard coefficients 1, 2, 1/2, 1/2)
// on (log m11, log m22, m13 / m11, m31), a parameterization in which the lobe width is
// scale-free from alpha = 1e-4 to 1, terminated when the objective's relative spread over the
// simplex falls below options::tolerance or after options::max_evaluations evaluations.
//
// Table. Node (t, a) of an N x N table has x = t / (N - 1), cos theta_v = max(1 - x^2, cos_min)
// and roughness r = a / (N - 1), alpha = max(r^2, alpha_min) (see ltc/shading/table.hpp). As in the
// paper's code, the normal-incidence nodes are fitted first, from roughness 1 (started at the
// cosine, M = I) down to roughness 0, each started from the previous one; then each row of
// constant roughness is fitted from its normal-incidence node towards grazing angles, each node
// started from its neighbour. Rows are independent work items handed to std::threads, so the
// result does not depend on the number of threads. The stored inverse matrix is divided by its
// middle element m_inv[1][1] (= 1 / m22 > 0, so the distribution is unchanged).
//
// Everything is computed in double precision and is deterministic: the same binary gives the
// same table bit for bit, whatever the thread count. The fit's arithmetic lives in this header
// (its own 3x3 inverse, cosine sampler and normalization) and in the BRDF model, so that changes
// elsewhere in the library do not move the bits of a generated table.
#pragma once

#include <ltc/fitting/brdf/model.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/shading/table.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace ltc {
namespace fit {

// ---------------------------------------------------------------------------------------------
// Nelder-Mead
// ---------------------------------------------------------------------------------------------

template <std::size_t Dim>
struct nelder_mead_result {
    std::array<double, Dim> x{};  ///< best point
    double value = 0;             ///< objective at x
    int evaluations = 0;
};

/// Minimizes f over R^Dim from the simplex {start, start + step_i e_i}. Deterministic (ties are
/// broken by vertex order); NaN values count as +infinity. Stops when
/// (f_worst - f_best) <= tolerance * (|f_best| + |f_worst|) / 2 (+ a tiny absolute floor), or
/// after max_evaluations evaluations of f.
template <std::size_t Dim, typename F>
nelder_mead_result<Dim> nelder_mead(F&& f, const std::array<double, Dim>& start, const std::array<double, Dim>& step,
                                    double tolerance, int max_evaluations) {
    using point = std::array<double, Dim>;
    constexpr std::size_t n = Dim + 1;
    std::array<point, n> s;
    std::array<double, n> fs;
    int evaluations = 0;
    const auto eval = [&](const point& p) {
        ++evaluations;
        const double v = f(p);
        return v == v ? v : std::numeric_limits<double>::infinity();
    };
    for (std::size_t i = 0; i < n; ++i) {
        s[i] = start;
        if (i > 0) s[i][i - 1] += step[i - 1];
        fs[i] = eval(s[i]);
    }
    std::array<std::size_t, n> order;
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    const auto sort = [&] {
        // Stable insertion sort by value: deterministic ordering of equal values.
        for (std::size_t i = 1; i < n; ++i)
            for (std::size_t j = i; j > 0 && fs[order[j]] < fs[order[j - 1]]; --j) std::swap(order[j], order[j - 1]);
    };
    const auto combine = [](const point& a, const point& b, double t) {  // a + t (b - a)
        point r;
        for (std::size_t k = 0; k < Dim; ++k) r[k] = a[k] + t * (b[k] - a[k]);
        return r;
    };
    for (;;) {
        sort();
        const std::size_t best = order[0], worst = order[n - 1], second = order[n - 2];
        const double lo = fs[best], hi = fs[worst];
        if (hi - lo <= tolerance * 0.5 * (std::abs(lo) + std::abs(hi)) + 1e-300) break;
        if (evaluations >= max_evaluations) break;
        point c{};
        for (std::size_t i = 0; i + 1 < n; ++i)
            for (std::size_t k = 0; k < Dim; ++k) c[k] += s[order[i]][k];
        for (std::size_t k = 0; k < Dim; ++k) c[k] /= double(Dim);
        const point xr = combine(c, s[worst], -1.0);
        const double fr = eval(xr);
        if (fr < lo) {
            const point xe = combine(c, s[worst], -2.0);
            const double fe = eval(xe);
            if (fe < fr)
                s[worst] = xe, fs[worst] = fe;
            else
                s[worst] = xr, fs[worst] = fr;
            continue;
        }
        if (fr < fs[second]) {
            s[worst] = xr, fs[worst] = fr;
            continue;
        }
        if (fr < hi) {  // outside contraction
            const point xc = combine(c, xr, 0.5);
            const double fc = eval(xc);
            if (fc <= fr) {
                s[worst] = xc, fs[worst] = fc;
                continue;
            }
        } else {  // inside contraction
            const point xc = combine(c, s[worst], 0.5);
            const double fc = eval(xc);
            if (fc < hi) {
                s[worst] = xc, fs[worst] = fc;
                continue;
            }
        }
        for (std::size_t i = 1; i < n; ++i) {  // shrink towards the best vertex
            const std::size_t v = order[i];
            s[v] = combine(s[best], s[v], 0.5);
            fs[v] = eval(s[v]);
        }
    }
    sort();
    nelder_mead_result<Dim> r;
    r.x = s[order[0]];
    r.value = fs[order[0]];
    r.evaluations = evaluations;
    return r;
}

// ---------------------------------------------------------------------------------------------
// Options, table coordinates
// ---------------------------------------------------------------------------------------------

/// Called on the thread that runs fit_table(), about every options::progress_interval seconds
/// and once at the end: `done` of `total` nodes are fitted.
using progress_callback = std::function<void(std::size_t done, std::size_t total)>;

struct options {
    int size = 64;                 ///< N: the table has N x N nodes
    double alpha_min = 1e-4;       ///< alpha = max(roughness^2, alpha_min) (paper code: 1e-4)
    double cos_theta_min = 7.9632671073326335e-4;  ///< cos(1.57): V.z = 0 leaves rho undefined
    int moment_samples = 64;       ///< n x n samples for magnitude, fresnel, average direction
    int error_samples = 32;        ///< n x n samples per distribution for the L3 error (paper: 32)
    int rounds = 2;                ///< proposal refreshes per node (see the file comment)
    int parameters = 4;            ///< 4: (m11, m22, m13, m31); 3: m31 = 0, as the paper's code
    double tolerance = 1e-5;       ///< Nelder-Mead relative tolerance on the objective (paper: 1e-5)
    int max_evaluations = 400;     ///< per Nelder-Mead run
    double initial_step = 0.1;     ///< simplex size of the first round (log / ratio units)
    unsigned threads = 0;          ///< worker threads for fit_table (0: all cores)
    double progress_interval = 0.1;  ///< seconds between progress callbacks
};

/// x = sqrt(1 - cos theta_v) of node t of n.
inline double node_x(int t, int n) { return n > 1 ? double(t) / double(n - 1) : 0.0; }
/// cos theta_v of node t of n: 1 - x^2, at least cos_theta_min.
inline double node_cos_theta(int t, int n, double cos_theta_min) {
    const double x = node_x(t, n);
    return std::max(1.0 - x * x, cos_theta_min);
}
/// Roughness of node a of n.
inline double node_roughness(int a, int n) { return n > 1 ? double(a) / double(n - 1) : 1.0; }
/// alpha of node a of n: max(roughness^2, alpha_min).
inline double node_alpha(int a, int n, double alpha_min) {
    const double r = node_roughness(a, n);
    return std::max(r * r, alpha_min);
}

/// v / |v|, or 0 for v = 0 (local, so that the fit depends on no other header's rounding).
inline glm::dvec3 normalize_or_zero(const glm::dvec3& v) {
    const double l2 = glm::dot(v, v);
    return l2 > 0 ? v / std::sqrt(l2) : glm::dvec3(0.0);
}

// ---------------------------------------------------------------------------------------------
// Per-node BRDF quantities
// ---------------------------------------------------------------------------------------------

struct moments {
    double magnitude = 0;                   ///< integral of f
    double fresnel = 0;                     ///< integral of f (1 - V.H)^5
    glm::dvec3 average_direction{0, 0, 1};  ///< integral of f L, y zeroed, normalized
};

/// Magnitude, Fresnel term and average direction of f(L) = Brdf<double>::eval(V, L, alpha) by the
/// midpoint rule on an n x n grid through Brdf's importance sampler.
template <template <typename> class Brdf>
moments compute_moments(const glm::dvec3& V, double alpha, int n) {
    using B = Brdf<double>;
    double m = 0, fr = 0;
    glm::dvec3 dir(0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 u((i + 0.5) / n, (j + 0.5) / n);
            const glm::dvec3 L = B::sample(V, u, alpha);
            const double p = B::pdf(V, L, alpha);
            if (!(p > 0) || !(L.z > 0)) continue;
            const double e = B::eval(V, L, alpha);
            const double w = e / p;
            if (!(w > 0) || !std::isfinite(w)) continue;
            const glm::dvec3 H = normalize_or_zero(V + L);
            const double c = 1.0 - glm::clamp(glm::dot(V, H), 0.0, 1.0);
            const double c2 = c * c;
            m += w;
            fr += w * c2 * c2 * c;
            dir += w * L;
        }
    moments r;
    const double inv = 1.0 / (double(n) * double(n));
    r.magnitude = m * inv;
    r.fresnel = fr * inv;
    dir.y = 0;
    const double len = glm::length(dir);
    r.average_direction = len > 0 ? dir / len : glm::dvec3(0, 0, 1);
    return r;
}

// ---------------------------------------------------------------------------------------------
// LTC parameters and the error metric
// ---------------------------------------------------------------------------------------------

/// M = R * [m11 0 m13; 0 m22 0; m31 0 1] with R the rotation about y taking +z to `axis`.
struct ltc_parameters {
    double m11 = 1, m22 = 1, m13 = 0, m31 = 0;
    glm::dvec3 axis{0, 0, 1};  ///< unit, in the xz-plane

    glm::dmat3 matrix() const {
        const glm::dmat3 R(glm::dvec3(axis.z, 0, -axis.x), glm::dvec3(0, 1, 0), axis);
        const glm::dmat3 B(glm::dvec3(m11, 0, m31), glm::dvec3(0, m22, 0), glm::dvec3(m13, 0, 1));
        return R * B;
    }
};

/// Inverse and |det| of a matrix with the structure of an isotropic LTC, [a 0 b; 0 c 0; d 0 e]
/// (rows; GLM: a = m[0][0], b = m[2][0], c = m[1][1], d = m[0][2], e = m[2][2], the other four
/// elements 0): [e 0 -b; 0 (ae - bd)/c 0; -d 0 a] / (ae - bd). Closed form, so that the fit's
/// numbers (and the shipped table's bits) depend on nothing but this header and the BRDF.
struct structured_inverse {
    glm::dmat3 inverse{1.0};
    double abs_determinant = 1;  ///< |det| of the *input* matrix
    bool ok = true;              ///< false for a singular or non-finite input
};

inline structured_inverse invert_structured(const glm::dmat3& m) {
    const double a = m[0][0], b = m[2][0], c = m[1][1], d = m[0][2], e = m[2][2];
    const double det2 = a * e - b * d;
    structured_inverse r;
    r.inverse = glm::dmat3(0.0);
    r.inverse[0][0] = e / det2;
    r.inverse[2][0] = -b / det2;
    r.inverse[0][2] = -d / det2;
    r.inverse[2][2] = a / det2;
    r.inverse[1][1] = 1.0 / c;
    r.abs_determinant = std::abs(det2 * c);
    r.ok = det2 != 0 && c != 0 && std::isfinite(r.abs_determinant) && std::isfinite(r.inverse[0][0]) &&
           std::isfinite(r.inverse[2][0]) && std::isfinite(r.inverse[0][2]) && std::isfinite(r.inverse[2][2]) &&
           std::isfinite(r.inverse[1][1]) && r.abs_determinant > 0;
    return r;
}

/// The inverse of M (structured, see invert_structured) divided by its middle element
/// M^-1[1][1] = 1 / M[1][1]: [e c, -b c; -d c, a c] / (ae - bd) in the xz-block, 1 in the middle.
inline glm::dmat3 normalized_inverse(const glm::dmat3& M) {
    glm::dmat3 mi = invert_structured(M).inverse;
    const double c = M[1][1];
    mi[0][0] *= c;
    mi[2][0] *= c;
    mi[0][2] *= c;
    mi[2][2] *= c;
    mi[1][1] = 1;
    return mi;
}

/// Direction of the clamped cosine for u in [0, 1)^2 (Algorithm 1's D_o sampler, as
/// ltc::clamped_cosine): cos theta = sqrt(1 - u.x), phi = 2 pi u.y.
inline glm::dvec3 sample_cosine(const glm::dvec2& u) {
    const double cos_theta = std::sqrt(1.0 - u.x);
    const double sin_theta = std::sqrt(u.x);
    const double phi = 2.0 * pi<double>() * u.y;
    return glm::dvec3(std::cos(phi) * sin_theta, std::sin(phi) * sin_theta, cos_theta);
}

/// A frozen set of sample directions with f(L) and the MIS weight 1 / (sum_k n_k p_k(L)):
/// sum_i w_i g(L_i) estimates the integral of g over the sphere.
class sample_set {
  public:
    void clear() { x_.clear(), y_.clear(), z_.clear(), f_.clear(), w_.clear(); }
    void add(const glm::dvec3& L, double f, double w) {
        x_.push_back(L.x), y_.push_back(L.y), z_.push_back(L.z), f_.push_back(f), w_.push_back(w);
    }
    std::size_t size() const { return x_.size(); }

    /// What all() returns: the estimates sum_i w_i g(L_i) of the integrals of |f - m D| (l1),
    /// |f - m D|^3 (l3), f (f1) and f^3 (f3), m the magnitude and D the LTC of m_inv. Both l3()
    /// and all() assume m_inv has the structure of an isotropic LTC (invert_structured).
    struct sums {
        double l1 = 0, l3 = 0, f1 = 0, f3 = 0;
    };

    /// The L3 error only (the objective): the inner loop of the fit. Four partial sums in a
    /// fixed order (deterministic, and independent terms that the compiler can vectorize).
    double l3(const glm::dmat3& m_inv, double magnitude) const {
        const double a = m_inv[0][0], b = m_inv[2][0], c = m_inv[1][1], d = m_inv[0][2], e = m_inv[2][2];
        const double k = magnitude * std::abs(c * (a * e - b * d)) / pi<double>();
        const double* xs = x_.data();
        const double* ys = y_.data();
        const double* zs = z_.data();
        const double* fs = f_.data();
        const double* ws = w_.data();
        // D(L) = D_o(v / |v|) |det| / |v|^3 = max(0, v.z) |det| / (pi |v|^4), v = M^-1 L.
        const auto term = [&](std::size_t i) {
            const double x = a * xs[i] + b * zs[i];
            const double y = c * ys[i];
            const double z = d * xs[i] + e * zs[i];
            const double l2 = x * x + y * y + z * z;
            const double g = k * std::max(z, 0.0) / (l2 * l2);
            const double diff = std::abs(fs[i] - g);
            return ws[i] * diff * diff * diff;
        };
        const std::size_t n = x_.size();
        double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
        std::size_t i = 0;
        for (; i + 4 <= n; i += 4) {
            s0 += term(i);
            s1 += term(i + 1);
            s2 += term(i + 2);
            s3 += term(i + 3);
        }
        for (; i < n; ++i) s0 += term(i);
        return (s0 + s1) + (s2 + s3);
    }

    sums all(const glm::dmat3& m_inv, double magnitude) const {
        const double k = magnitude * invert_structured(m_inv).abs_determinant / pi<double>();
        sums s;
        for (std::size_t i = 0; i < x_.size(); ++i) {
            const glm::dvec3 w = m_inv * glm::dvec3(x_[i], y_[i], z_[i]);
            const double l2 = glm::dot(w, w);
            const double g = k * std::max(w.z, 0.0) / (l2 * l2);
            const double diff = std::abs(f_[i] - g);
            s.l1 += w_[i] * diff;
            s.l3 += w_[i] * diff * diff * diff;
            s.f1 += w_[i] * f_[i];
            s.f3 += w_[i] * f_[i] * f_[i] * f_[i];
        }
        return s;
    }

  private:
    std::vector<double> x_, y_, z_, f_, w_;
};

/// Density of the LTC of m_inv at the unit direction L (1 for the normalized distribution).
inline double ltc_density(const glm::dmat3& m_inv, double abs_det_inv, const glm::dvec3& L) {
    const glm::dvec3 w = m_inv * L;
    const double l2 = glm::dot(w, w);
    return l2 > 0 ? std::max(w.z, 0.0) * abs_det_inv / (pi<double>() * l2 * l2) : 0.0;
}

/// Fills `out` with the MIS estimator of the paper: n x n midpoint samples through the BRDF's
/// sampler and n x n through the LTC of the matrix M, f evaluated at each, weights
/// 1 / (n^2 p_brdf + n^2 p_ltc).
template <template <typename> class Brdf>
void make_sample_set(const glm::dvec3& V, double alpha, const glm::dmat3& M, int n, sample_set& out) {
    using B = Brdf<double>;
    const structured_inverse inv = invert_structured(M);
    const glm::dmat3 m_inv = inv.inverse;
    const double abs_det_inv = 1.0 / inv.abs_determinant;
    const double count = double(n) * double(n);
    out.clear();
    const auto add = [&](const glm::dvec3& L) {
        const double f = L.z > 0 ? B::eval(V, L, alpha) : 0.0;
        const double p = count * (B::pdf(V, L, alpha) + ltc_density(m_inv, abs_det_inv, L));
        if (p > 0 && std::isfinite(p) && std::isfinite(f)) out.add(L, f, 1.0 / p);
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 u((i + 0.5) / n, (j + 0.5) / n);
            add(B::sample(V, u, alpha));
            add(normalize_or_zero(M * sample_cosine(u)));
        }
}

// ---------------------------------------------------------------------------------------------
// Fitting one node
// ---------------------------------------------------------------------------------------------

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
    double step = opt.initial_step;
    for (int round = 0; round < std::max(1, opt.rounds); ++round) {
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
/// and the better of the two is kept. (It never triggers for the shipped 64 x 64 table.)
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
    return r;
}

// ---------------------------------------------------------------------------------------------
// Independent error measurement
// ---------------------------------------------------------------------------------------------

struct node_error {
    double relative_l1 = 0;  ///< integral |f - m D| / integral f: bounds |shading error| / albedo
    double relative_l3 = 0;  ///< (integral |f - m D|^3 / integral f^3)^(1/3)
    double albedo = 0;       ///< integral f (of this estimator)
};

/// Measures how well magnitude * D(m_inv) approximates f = rho cos at one node, with the MIS
/// estimator on n x n samples per distribution (independent of the fit when n differs from
/// options::error_samples). relative_l1 bounds the relative error of the shading of any
/// constant polygonal light: |integral over P of (f - m D)| <= integral |f - m D|.
template <template <typename> class Brdf>
node_error measure_error(double cos_theta, double alpha, const glm::dmat3& m_inv, double magnitude, int n) {
    const glm::dvec3 V = brdf::view_from_cos(cos_theta);
    sample_set samples;
    make_sample_set<Brdf>(V, alpha, invert_structured(m_inv).inverse, n, samples);
    const auto s = samples.all(m_inv, magnitude);
    node_error e;
    e.albedo = s.f1;
    e.relative_l1 = s.f1 > 0 ? s.l1 / s.f1 : 0.0;
    e.relative_l3 = s.f3 > 0 ? std::cbrt(s.l3 / s.f3) : 0.0;
    return e;
}

// ---------------------------------------------------------------------------------------------
// Tables
// ---------------------------------------------------------------------------------------------

struct table {
    int size = 0;
    std::vector<node_result> nodes;  ///< nodes[a * size + t]: a along roughness, t along x

    const node_result& at(int t, int a) const { return nodes[std::size_t(a) * std::size_t(size) + std::size_t(t)]; }
    node_result& at(int t, int a) { return nodes[std::size_t(a) * std::size_t(size) + std::size_t(t)]; }

    /// The size * size * 6 floats of ltc/shading/table.hpp.
    std::vector<float> packed() const {
        std::vector<float> d;
        d.reserve(nodes.size() * channel::count);
        for (const node_result& n : nodes) {
            d.push_back(float(n.m_inv[0][0]));
            d.push_back(float(n.m_inv[0][2]));
            d.push_back(float(n.m_inv[2][0]));
            d.push_back(float(n.m_inv[2][2]));
            d.push_back(float(n.magnitude));
            d.push_back(float(n.fresnel));
        }
        return d;
    }
};

/// The normal-incidence nodes (t = 0) of every row, fitted in sequence from roughness 1 (started
/// at the cosine) down to roughness 0, each started from the previous one. result[a] is row a's.
template <template <typename> class Brdf>
std::vector<node_result> fit_normal_incidence(const options& opt) {
    const int n = opt.size;
    std::vector<node_result> r(std::size_t(std::max(n, 0)));
    ltc_parameters start;
    for (int a = n - 1; a >= 0; --a) {
        r[std::size_t(a)] = fit_node<Brdf>(node_cos_theta(0, n, opt.cos_theta_min), node_alpha(a, n, opt.alpha_min),
                                           start, opt);
        start = r[std::size_t(a)].parameters;
    }
    return r;
}

/// Row a (constant roughness), t = 1 .. size - 1, each node started from its neighbour t - 1;
/// `normal_incidence` is the row's node t = 0. on_node(t) is called after each node.
template <template <typename> class Brdf, typename OnNode>
void fit_row(int a, const node_result& normal_incidence, const options& opt, node_result* row, OnNode&& on_node) {
    const int n = opt.size;
    row[0] = normal_incidence;
    const double alpha = node_alpha(a, n, opt.alpha_min);
    for (int t = 1; t < n; ++t) {
        row[t] = fit_node<Brdf>(node_cos_theta(t, n, opt.cos_theta_min), alpha, row[t - 1].parameters, opt);
        on_node(t);
    }
}

template <template <typename> class Brdf>
std::vector<node_result> fit_row(int a, const node_result& normal_incidence, const options& opt) {
    std::vector<node_result> row(std::size_t(std::max(opt.size, 1)));
    fit_row<Brdf>(a, normal_incidence, opt, row.data(), [](int) {});
    return row;
}

/// Fits the whole size x size table on options::threads threads (see the file comment).
template <template <typename> class Brdf>
table fit_table(const options& opt, const progress_callback& progress = {}) {
    if (opt.size < 2) throw std::invalid_argument("ltc::fit::fit_table: size must be at least 2");
    const int n = opt.size;
    table tab;
    tab.size = n;
    tab.nodes.resize(std::size_t(n) * std::size_t(n));
    const std::size_t total = tab.nodes.size();

    std::atomic<std::size_t> done{0};
    std::atomic<int> next_row{0};
    std::mutex mutex;
    std::condition_variable finished;
    int running = 0;
    std::exception_ptr failure;

    // The callback runs on this thread only; if it throws, the workers stop after their current
    // row and the exception is rethrown once they have joined.
    const auto report = [&] {
        if (!progress) return;
        {
            std::lock_guard<std::mutex> lock(mutex);
            if (failure) return;
        }
        try {
            progress(done.load(), total);
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex);
            if (!failure) failure = std::current_exception();
            next_row.store(n);
        }
    };

    unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
    threads = std::min<unsigned>(threads, unsigned(n));

    // Phase 1, sequential: the normal-incidence chain (one-parameter fits, cheap).
    const std::vector<node_result> normal = fit_normal_incidence<Brdf>(opt);
    done += std::size_t(n);
    report();

    // Phase 2: rows in parallel, each a deterministic function of its normal-incidence node.
    const auto worker = [&] {
        try {
            for (;;) {
                const int a = next_row.fetch_add(1);
                if (a >= n) break;
                node_result* row = &tab.nodes[std::size_t(a) * std::size_t(n)];
                fit_row<Brdf>(a, normal[std::size_t(a)], opt, row, [&](int) { done.fetch_add(1); });
            }
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex);
            if (!failure) failure = std::current_exception();
            next_row.store(n);
        }
        std::lock_guard<std::mutex> lock(mutex);
        --running;
        finished.notify_all();
    };
    std::vector<std::thread> pool;
    pool.reserve(threads);
    try {
        for (unsigned i = 0; i < threads; ++i) {
            {
                std::lock_guard<std::mutex> lock(mutex);
                ++running;
            }
            try {
                pool.emplace_back(worker);
            } catch (...) {
                std::lock_guard<std::mutex> lock(mutex);
                --running;
                throw;
            }
        }
    } catch (...) {  // a thread could not be started: stop the others, then report
        next_row.store(n);
        for (std::thread& t : pool) t.join();
        throw;
    }
    {
        std::unique_lock<std::mutex> lock(mutex);
        const auto interval = std::chrono::duration<double>(std::max(opt.progress_interval, 0.001));
        while (running > 0) {
            finished.wait_for(lock, interval);
            if (running == 0) break;
            lock.unlock();
            report();
            lock.lock();
        }
    }
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
    report();
    return tab;
}

}  // namespace fit
}  // namespace ltc
