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
// The reference-style fitter (namespace reference_style, benchmarks/reference_style_fit.hpp)
// reproduces fitLTC.cpp's choices; its file comment lists them, and the differences.
#include "reference_style_fit.hpp"

#include <benchmark/benchmark.h>

#include <ltc/brdf/ggx.hpp>
#include <ltc/fitting/fit.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <ctime>
#include <vector>

namespace {

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
