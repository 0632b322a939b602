// A reference-style LTC fitter for benchmarks/bench_fit.cpp, configured like the paper's code
// release (selfshadow/ltc_code, fit/fitLTC.cpp), timed side by side with this library's fitter.
//
// This reference-style fitter reproduces fitLTC.cpp's choices:
//   - error: the L3 MIS estimator over 32 x 32 LTC samples and 32 x 32 BRDF samples, the LTC
//     samples redrawn from the *current* candidate at every evaluation (so every evaluation
//     calls the BRDF 2 x 32 x 32 times), computeError() line by line;
//   - parameters (m11, m22, m13) with m31 = 0, M = [X Y Z] [m11 0 m13; 0 m22 0; 0 0 1], the frame
//     rotated to the average direction, m11 and m22 clamped to >= 1e-7 (FitLTC::update);
//   - NelderMead<3>(result, start, delta = 0.05, tolerance = 1e-5, maxIters = 100): absolute
//     initial simplex steps, Numerical Recipes' termination 2|f_hi - f_lo| < tol (|f_hi| + |f_lo|),
//     at most 100 iterations; the downhill simplex of the release's nelder_mead.h;
//   - order and seeding of fitTab(): roughness from 1 down to 0; in each row theta from normal
//     incidence (isotropic, started from the previous row's normal-incidence fit, the cosine for
//     roughness 1) to grazing (started from the previous theta); one thread;
//   - table coordinates x = t / 63, cos theta = 1 - x^2, theta <= 1.57; alpha = max(r^2, 1e-4);
//     magnitude, Fresnel and average direction over 32 x 32 BRDF samples (computeAvgTerms).
// Differences, on purpose: it runs in double (the release uses float) and calls the same BRDF
// model as this library (ltc::brdf::ggx<double>, a visible-normal sampler) instead of the
// release's brdf_ggx.h, so that the comparison is about the fitting method only. Its MIN_ALPHA
// is 1e-4 (the 2016 release's; later ones use 1e-5, which ltc::brdf::ggx clamps to 1e-4).
#pragma once

#include <ltc/brdf/ggx.hpp>
#include <ltc/fitting/fit.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace reference_style {

inline constexpr int nsample = 32;
inline constexpr double min_alpha = 1e-4;

/// fit/LTC.h: the LTC of M = [X Y Z] * [m11 0 m13; 0 m22 0; 0 0 1], times the magnitude.
struct ltc_state {
    double magnitude = 1;
    double m11 = 1, m22 = 1, m13 = 0;
    glm::dvec3 X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};
    glm::dmat3 M{1.0}, invM{1.0};
    double detM = 1;

    void update() {
        M = glm::dmat3(X, Y, Z) * glm::dmat3(m11, 0, 0, 0, m22, 0, m13, 0, 1);
        invM = glm::inverse(M);
        detM = std::abs(glm::determinant(M));
    }
    double eval(const glm::dvec3& L) const {
        const glm::dvec3 Loriginal = glm::normalize(invM * L);
        const glm::dvec3 L_ = M * Loriginal;
        const double l = glm::length(L_);
        const double jacobian = detM / (l * l * l);
        const double D = 1.0 / ltc::pi<double>() * std::max(0.0, Loriginal.z);
        return magnitude * D / jacobian;
    }
    glm::dvec3 sample(double u1, double u2) const {
        const double theta = std::acos(std::sqrt(u1));
        const double phi = 2.0 * ltc::pi<double>() * u2;
        return glm::normalize(M * glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                             std::cos(theta)));
    }
};

using brdf = ltc::brdf::ggx<double>;

/// fitLTC.cpp computeError(): MIS over LTC samples (of the current candidate) and BRDF samples.
inline double compute_error(const ltc_state& ltc, const glm::dvec3& V, double alpha) {
    double error = 0;
    for (int j = 0; j < nsample; ++j)
        for (int i = 0; i < nsample; ++i) {
            const double u1 = (i + 0.5) / nsample, u2 = (j + 0.5) / nsample;
            {
                const glm::dvec3 L = ltc.sample(u1, u2);
                const double pdf_brdf = brdf::pdf(V, L, alpha), eval_brdf = brdf::eval(V, L, alpha);
                const double eval_ltc = ltc.eval(L), pdf_ltc = eval_ltc / ltc.magnitude;
                double e = std::abs(eval_brdf - eval_ltc);
                e = e * e * e;
                error += e / (pdf_ltc + pdf_brdf);
            }
            {
                const glm::dvec3 L = brdf::sample(V, glm::dvec2(u1, u2), alpha);
                const double pdf_brdf = brdf::pdf(V, L, alpha), eval_brdf = brdf::eval(V, L, alpha);
                const double eval_ltc = ltc.eval(L), pdf_ltc = eval_ltc / ltc.magnitude;
                double e = std::abs(eval_brdf - eval_ltc);
                e = e * e * e;
                error += e / (pdf_ltc + pdf_brdf);
            }
        }
    return error / (nsample * nsample);
}

/// The release's nelder_mead.h (downhill simplex, Numerical Recipes termination), Dim = 3.
template <typename F>
std::array<double, 3> nelder_mead(const std::array<double, 3>& start, double delta, double tolerance, int max_iters,
                                  F&& f) {
    constexpr int D = 3, P = D + 1;
    double s[P][D], fv[P];
    for (int i = 0; i < P; ++i) {
        for (int k = 0; k < D; ++k) s[i][k] = start[std::size_t(k)];
        if (i > 0) s[i][i - 1] += delta;
    }
    for (int i = 0; i < P; ++i) fv[i] = f(s[i]);
    int lo = 0, hi = 0, nh = 0;
    for (int j = 0; j < max_iters; ++j) {
        lo = hi = nh = 0;
        for (int i = 1; i < P; ++i) {
            if (fv[i] < fv[lo]) lo = i;
            if (fv[i] > fv[hi]) {
                nh = hi;
                hi = i;
            } else if (fv[i] > fv[nh]) {
                nh = i;
            }
        }
        const double a = std::abs(fv[lo]), b = std::abs(fv[hi]);
        if (2.0 * std::abs(a - b) < (a + b) * tolerance) break;
        double o[D] = {0, 0, 0};
        for (int i = 0; i < P; ++i)
            if (i != hi)
                for (int k = 0; k < D; ++k) o[k] += s[i][k];
        for (int k = 0; k < D; ++k) o[k] /= D;
        double r[D];
        for (int k = 0; k < D; ++k) r[k] = o[k] + (o[k] - s[hi][k]);
        const double fr = f(r);
        if (fr < fv[nh]) {
            if (fr < fv[lo]) {
                double e[D];
                for (int k = 0; k < D; ++k) e[k] = o[k] + 2.0 * (o[k] - s[hi][k]);
                const double fe = f(e);
                if (fe < fr) {
                    for (int k = 0; k < D; ++k) s[hi][k] = e[k];
                    fv[hi] = fe;
                    continue;
                }
            }
            for (int k = 0; k < D; ++k) s[hi][k] = r[k];
            fv[hi] = fr;
            continue;
        }
        double c[D];
        for (int k = 0; k < D; ++k) c[k] = o[k] - 0.5 * (o[k] - s[hi][k]);
        const double fc = f(c);
        if (fc < fv[hi]) {
            for (int k = 0; k < D; ++k) s[hi][k] = c[k];
            fv[hi] = fc;
            continue;
        }
        for (int q = 0; q < P; ++q) {
            if (q == lo) continue;
            for (int k = 0; k < D; ++k) s[q][k] = s[lo][k] + 0.5 * (s[q][k] - s[lo][k]);
            fv[q] = f(s[q]);
        }
    }
    return {s[lo][0], s[lo][1], s[lo][2]};
}

/// One node of fitTab(): `ltc` holds the previous fit (the first guess) and receives this one.
inline void fit_node(ltc_state& ltc, int t, int a, int n, ltc::fit::node_result& out) {
    const double x = t / double(n - 1);
    const double ct = 1.0 - x * x;
    const double theta = std::min(1.57, std::acos(ct));
    const glm::dvec3 V(std::sin(theta), 0, std::cos(theta));
    const double roughness = a / double(n - 1);
    const double alpha = std::max(roughness * roughness, min_alpha);

    const ltc::fit::moments mom = ltc::fit::compute_moments<ltc::brdf::ggx>(V, alpha, nsample);
    ltc.magnitude = mom.magnitude;
    bool isotropic;
    if (t == 0) {
        ltc.X = {1, 0, 0};
        ltc.Y = {0, 1, 0};
        ltc.Z = {0, 0, 1};
        if (a == n - 1) ltc.m11 = ltc.m22 = 1;  // otherwise: the previous row's t = 0 fit, still in ltc
        ltc.m13 = 0;
        ltc.update();
        isotropic = true;
    } else {
        const glm::dvec3 L = mom.average_direction;
        ltc.X = {L.z, 0, -L.x};
        ltc.Y = {0, 1, 0};
        ltc.Z = L;
        ltc.update();
        isotropic = false;
    }
    const auto update = [&](const double* p) {
        const double m11 = std::max(p[0], 1e-7), m22 = std::max(p[1], 1e-7);
        ltc.m11 = m11;
        ltc.m22 = isotropic ? m11 : m22;
        ltc.m13 = isotropic ? 0.0 : p[2];
        ltc.update();
    };
    const std::array<double, 3> result = nelder_mead({ltc.m11, ltc.m22, ltc.m13}, 0.05, 1e-5, 100, [&](const double* p) {
        update(p);
        return compute_error(ltc, V, alpha);
    });
    update(result.data());
    out.parameters.m11 = ltc.m11;
    out.parameters.m22 = ltc.m22;
    out.parameters.m13 = ltc.m13;
    out.parameters.axis = ltc.Z;
    out.m_inv = ltc::fit::normalized_inverse(ltc.M);
    out.magnitude = mom.magnitude;
    out.fresnel = mom.fresnel;
}

/// fitTab(): rows from roughness 1 down, each from normal incidence to grazing; one thread.
inline ltc::fit::table fit_table(int n) {
    ltc::fit::table tab;
    tab.size = n;
    tab.nodes.resize(std::size_t(n) * std::size_t(n));
    ltc_state ltc, row_start;
    for (int a = n - 1; a >= 0; --a) {
        ltc = row_start;  // the previous row's normal-incidence fit
        for (int t = 0; t < n; ++t) {
            fit_node(ltc, t, a, n, tab.at(t, a));
            if (t == 0) row_start = ltc;
        }
    }
    return tab;
}

}  // namespace reference_style
