// ltc/fitting/error_metric.hpp -- the fit's objective (paper section 4): the L3 distance between
// f = rho cos and magnitude * D, estimated by MIS over a frozen sample set (sample_set,
// make_sample_set), and the same estimator as an independent check of a fitted node
// (node_error, measure_error).
//
//   E(M) = integral over the sphere of |f(L) - magnitude * D_M(L)|^3 dL
//        ~= sum_i |f - m D|^3 / (n^2 p_brdf + n^2 p_ltc)   (n x n midpoints through each sampler)
//
// Conventions: double, the local frame of ltc/fitting/fit.hpp; the LTC's samples come from a
// frozen proposal, re-centred each round (make_sample_set). L3, as in the paper, weighs the peak
// of the lobe, where highlights come from, more than the tails; node_error reports L1 too.
#pragma once

#include <ltc/config.hpp>

#include <ltc/brdf/model.hpp>
#include <ltc/fitting/ltc_parameters.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

LTC_NAMESPACE_BEGIN
namespace fit {

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
    /// |f - m D|^3 (l3), f (f1) and f^3 (f3), m the magnitude and D the LTC of m_inv. l3() and
    /// all() of (m_inv, magnitude) assume m_inv has the structure of an isotropic LTC
    /// (invert_structured); their overloads of (m_inv, |det m_inv|, magnitude) take any m_inv.
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
        return sum4(term);
    }

    /// The L3 error for any m_inv (anisotropic LTCs), |det m_inv| given.
    double l3(const glm::dmat3& m_inv, double abs_det, double magnitude) const {
        const glm::dmat3& a = m_inv;
        const double k = magnitude * abs_det / pi<double>();
        const auto term = [&](std::size_t i) {
            const double x = a[0][0] * x_[i] + a[1][0] * y_[i] + a[2][0] * z_[i];
            const double y = a[0][1] * x_[i] + a[1][1] * y_[i] + a[2][1] * z_[i];
            const double z = a[0][2] * x_[i] + a[1][2] * y_[i] + a[2][2] * z_[i];
            const double l2 = x * x + y * y + z * z;
            const double d = std::abs(f_[i] - k * std::max(z, 0.0) / (l2 * l2));
            return w_[i] * d * d * d;
        };
        return sum4(term);
    }

    sums all(const glm::dmat3& m_inv, double magnitude) const {
        return all(m_inv, invert_structured(m_inv).abs_determinant, magnitude);
    }

    /// all() for any m_inv, |det m_inv| given.
    sums all(const glm::dmat3& m_inv, double abs_det, double magnitude) const {
        const double k = magnitude * abs_det / pi<double>();
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
    /// sum_i term(i) in four partial sums in a fixed order (deterministic, and independent terms
    /// that the compiler can vectorize).
    template <typename Term>
    double sum4(const Term& term) const {
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

    std::vector<double> x_, y_, z_, f_, w_;
};

/// Fills `out` with the MIS estimator of the paper: n x n midpoint samples through the BRDF's
/// sampler and n x n through the LTC of the matrix M, f evaluated at each, weights
/// 1 / (n^2 p_brdf + n^2 p_ltc).
///
/// Error metric: the paper's L3 distance
///
///   E(M) = integral over the sphere of |f(L) - magnitude * D_M(L)|^3 dL,
///
/// estimated, like the paper's code, by multiple importance sampling with the balance heuristic
/// over two n x n midpoint grids (n = options::error_samples): one through Brdf::sample, one
/// through the LTC's own sampler (Algorithm 1): E ~= sum_i |f - m D|^3 / (n^2 p_brdf + n^2 p_ltc).
/// One change, for speed and for a smooth objective: the LTC samples are drawn from a *frozen*
/// proposal LTC (the starting point of the current round) instead of the current candidate, so
/// that f, p_brdf and p_ltc are computed once per round and each evaluation of E only evaluates
/// D_M (a 3x3 product and a division per sample, no BRDF call). Like the paper's, this is an
/// importance-sampling estimate of E for any candidate (MIS with a fixed proposal instead of a
/// moving one); it is most accurate near the proposal, so the fit runs options::rounds rounds,
/// each re-centring the proposal on the previous round's result, and the last round's proposal
/// is close to the final LTC as in the paper (ltc/fitting/fit_node.hpp). The frozen samples also
/// make E a fixed smooth function of the parameters during a minimization, so that Nelder-Mead
/// converges instead of chasing the noise of moving samples. Why L3 and not, say, L1 or L2: the
/// paper found that it gives the best visual results (it weighs the peak of the lobe, where
/// highlights come from, more than the tails); we keep it and report the result in both L1 and
/// L3 (node_result, measure_error).
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

}  // namespace fit
LTC_NAMESPACE_END
