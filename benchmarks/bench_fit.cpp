// Benchmarks of the LTC fit (ltc/fitting/fit.hpp): one node, one row, the full 64 x 64 GGX table with
// 1 and 2 threads, and, side by side, a reference-style fitter configured like the paper's code
// release (selfshadow/ltc_code, fit/fitLTC.cpp), timed on the same machine in the same run.
//
//   bench_fit                                   # everything (the reference table takes minutes)
//   bench_fit --benchmark_filter='table'        # the full tables only
//   bench_fit --benchmark_filter='^fit_'        # this library's fitter only
//
// The table benchmarks also report the quality of what they computed, measured the same way
// for both fitters, independently of either fit's own estimate: for every node of the table as
// stored (float m_inv and magnitude), an MIS estimate with 48 x 48 BRDF and 48 x 48 LTC samples of
//   l1 = integral |f - m D| / integral f            (bounds |polygon shading error| / albedo)
//   l3 = (integral |f - m D|^3 / integral f^3)^(1/3)
// with f = rho cos (GGX) and m D the table's approximation; counters *_mean and *_max. The
// counter process_cpu_s is the CPU time of all threads of the process during the fit (the
// "CPU" column only counts the main thread), a measure that a busy machine does not inflate.
//
// The reference-style fitter (namespace reference_style) reproduces fitLTC.cpp's choices:
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
#include <benchmark/benchmark.h>

#include <ltc/fitting/brdf/ggx.hpp>
#include <ltc/fitting/fit.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <ctime>
#include <vector>

namespace {

namespace reference_style {

constexpr int nsample = 32;
constexpr double min_alpha = 1e-4;

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
double compute_error(const ltc_state& ltc, const glm::dvec3& V, double alpha) {
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
void fit_node(ltc_state& ltc, int t, int a, int n, ltc::fit::node_result& out) {
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
ltc::fit::table fit_table(int n) {
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

constexpr int size = 64;
constexpr int measure_samples = 48;

/// The independent quality measure of the file comment, over the table as stored (floats).
void report_quality(benchmark::State& state, const ltc::fit::table& tab) {
    const ltc::fit::options opt;
    const std::vector<float> d = tab.packed();
    double l1 = 0, l1_max = 0, l3 = 0, l3_max = 0;
    for (int a = 0; a < tab.size; ++a)
        for (int t = 0; t < tab.size; ++t) {
            const std::size_t o = (std::size_t(a) * std::size_t(tab.size) + std::size_t(t)) * 6;
            glm::dmat3 m_inv(0.0);
            m_inv[0][0] = d[o + 0];
            m_inv[0][2] = d[o + 1];
            m_inv[2][0] = d[o + 2];
            m_inv[2][2] = d[o + 3];
            m_inv[1][1] = 1;
            const ltc::fit::node_error e = ltc::fit::measure_error<ltc::brdf::ggx>(
                ltc::fit::node_cos_theta(t, tab.size, opt.cos_theta_min), ltc::fit::node_alpha(a, tab.size, opt.alpha_min),
                m_inv, d[o + 4], measure_samples);
            l1 += e.relative_l1;
            l3 += e.relative_l3;
            l1_max = std::max(l1_max, e.relative_l1);
            l3_max = std::max(l3_max, e.relative_l3);
        }
    const double nodes = double(tab.size) * double(tab.size);
    state.counters["l1_mean"] = l1 / nodes;
    state.counters["l1_max"] = l1_max;
    state.counters["l3_mean"] = l3 / nodes;
    state.counters["l3_max"] = l3_max;
}

/// The normal-incidence chain and row 32 of this library's fit, for the node and row benchmarks.
struct fixture {
    ltc::fit::options opt;
    std::vector<ltc::fit::node_result> normal;
    std::vector<ltc::fit::node_result> row;
    fixture() {
        opt.size = size;
        normal = ltc::fit::fit_normal_incidence<ltc::brdf::ggx>(opt);
        row = ltc::fit::fit_row<ltc::brdf::ggx>(32, normal[32], opt);
    }
    static const fixture& get() {
        static const fixture f;
        return f;
    }
};

// ---- this library's fitter -------------------------------------------------------------------

/// One node (t = 32, roughness 32/63), started from its neighbour t = 31, as in the table.
void fit_node(benchmark::State& state) {
    const fixture& f = fixture::get();
    const double cos_theta = ltc::fit::node_cos_theta(32, size, f.opt.cos_theta_min);
    const double alpha = ltc::fit::node_alpha(32, size, f.opt.alpha_min);
    for (auto _ : state) {
        ltc::fit::node_result r = ltc::fit::fit_node<ltc::brdf::ggx>(cos_theta, alpha, f.row[31].parameters, f.opt);
        benchmark::DoNotOptimize(r);
    }
}
BENCHMARK(fit_node)->Unit(benchmark::kMillisecond);

/// One row (roughness 32/63, 63 nodes from normal incidence to grazing) on one thread.
void fit_row(benchmark::State& state) {
    const fixture& f = fixture::get();
    for (auto _ : state) {
        std::vector<ltc::fit::node_result> row = ltc::fit::fit_row<ltc::brdf::ggx>(32, f.normal[32], f.opt);
        benchmark::DoNotOptimize(row);
    }
}
BENCHMARK(fit_row)->Unit(benchmark::kMillisecond);

/// The full 64 x 64 table (what ltc_fit --brdf ggx computes), on state.range(0) threads.
void fit_table(benchmark::State& state) {
    ltc::fit::options opt;
    opt.size = size;
    opt.threads = unsigned(state.range(0));
    ltc::fit::table tab;
    const std::clock_t cpu = std::clock();
    for (auto _ : state) {
        tab = ltc::fit::fit_table<ltc::brdf::ggx>(opt);
        benchmark::DoNotOptimize(tab);
    }
    state.counters["process_cpu_s"] = double(std::clock() - cpu) / CLOCKS_PER_SEC;
    report_quality(state, tab);
}
BENCHMARK(fit_table)->ArgName("threads")->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

// ---- the reference-style fitter --------------------------------------------------------------

void reference_fit_node(benchmark::State& state) {
    const fixture& f = fixture::get();
    reference_style::ltc_state start;
    start.m11 = f.row[31].parameters.m11;
    start.m22 = f.row[31].parameters.m22;
    start.m13 = f.row[31].parameters.m13;
    for (auto _ : state) {
        reference_style::ltc_state ltc = start;
        ltc::fit::node_result r;
        reference_style::fit_node(ltc, 32, 32, size, r);
        benchmark::DoNotOptimize(r);
    }
}
BENCHMARK(reference_fit_node)->Unit(benchmark::kMillisecond);

void reference_fit_row(benchmark::State& state) {
    const fixture& f = fixture::get();
    for (auto _ : state) {
        reference_style::ltc_state ltc;
        ltc.m11 = ltc.m22 = f.normal[32].parameters.m11;
        std::vector<ltc::fit::node_result> row(size);
        for (int t = 0; t < size; ++t) reference_style::fit_node(ltc, t, 32, size, row[std::size_t(t)]);
        benchmark::DoNotOptimize(row);
    }
}
BENCHMARK(reference_fit_row)->Unit(benchmark::kMillisecond);

void reference_fit_table(benchmark::State& state) {
    ltc::fit::table tab;
    const std::clock_t cpu = std::clock();
    for (auto _ : state) {
        tab = reference_style::fit_table(size);
        benchmark::DoNotOptimize(tab);
    }
    state.counters["process_cpu_s"] = double(std::clock() - cpu) / CLOCKS_PER_SEC;
    report_quality(state, tab);
}
BENCHMARK(reference_fit_table)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
