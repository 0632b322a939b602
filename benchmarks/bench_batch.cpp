// Batch API (ltc/shading/batch.hpp) against the reference shader path (reference_shader.hpp), side by side
// over the same 4096 random configurations as bench_polygon (GGX-like M^-1, a quad crossing the
// horizon in about half of them): every benchmark evaluates all 4096 items per iteration and
// reports items/s (SetItemsProcessed), plus, as counters, the maximum absolute and relative error
// against the library's double-precision exact closed form.
//
// Built four times by CMake (benchmarks/CMakeLists.txt): bench_batch (the build type's flags: -O3
// in Release), bench_batch_o2 (-O2), bench_batch_avx2 and bench_batch_o2_avx2 (the same with
// -march=x86-64-v3, which exit without running where the CPU lacks AVX2 or FMA). Without -march
// the batch still runs its AVX2 or AVX-512 kernel where the CPU has it (run-time dispatch): the
// rows isa::baseline, isa::avx2 and isa::avx512 pin the instruction set. Run them with
// --benchmark_repetitions=5 and compare medians; the throughput ratio batch / reference is
// meaningful within one executable (both sides are compiled with the same flags).
#include "bench_main.hpp"
#include "configurations.hpp"
#include "reference_shader.hpp"

#include <ltc/shading/batch.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace {

constexpr std::size_t kItems = 4096;

using bench::config;
using bench::configs;

// The float inputs: array-of-structures for the scalar paths, structure-of-arrays for the batch.
struct inputs {
    std::vector<glm::mat3> m_inv;
    std::vector<std::array<glm::vec3, 4>> quad;
    std::vector<float> m[3][3];
    std::vector<float> x[4], y[4], z[4];

    inputs() {
        for (const config& c : configs()) {
            m_inv.push_back(glm::mat3(c.m_inv));
            std::array<glm::vec3, 4> q;
            for (int k = 0; k < 4; ++k) q[static_cast<std::size_t>(k)] = glm::vec3(c.quad[k]);
            quad.push_back(q);
            for (int col = 0; col < 3; ++col)
                for (int r = 0; r < 3; ++r) m[col][r].push_back(m_inv.back()[col][r]);
            for (std::size_t k = 0; k < 4; ++k) x[k].push_back(q[k].x), y[k].push_back(q[k].y), z[k].push_back(q[k].z);
        }
    }
    ltc::batch::quad_soa<float> soa() const {
        const float* e[3][3];
        for (int col = 0; col < 3; ++col)
            for (int r = 0; r < 3; ++r) e[col][r] = m[col][r].data();
        ltc::batch::quad_soa<float> s;
        s.m_inv = ltc::batch::matrices<float>::per_item(e);
        for (std::size_t k = 0; k < 4; ++k) s.x[k] = x[k].data(), s.y[k] = y[k].data(), s.z[k] = z[k].data();
        return s;
    }
};

const inputs& data() {
    static const inputs d;
    return d;
}

const std::vector<double>& exact() {
    static const std::vector<double> e = [] {
        std::vector<double> v;
        for (const config& c : configs())
            v.push_back(ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(c.m_inv).integrate(
                c.quad, 4, ltc::sidedness::two_sided));
        return v;
    }();
    return e;
}

void report_errors(benchmark::State& state, const std::vector<float>& out) {
    double max_abs = 0, max_rel = 0;
    for (std::size_t i = 0; i < kItems; ++i) {
        const double e = exact()[i], err = std::abs(static_cast<double>(out[i]) - e);
        max_abs = std::max(max_abs, err);
        if (e > 1e-3) max_rel = std::max(max_rel, err / e);
    }
    state.counters["max_abs_err"] = max_abs;
    state.counters["max_rel_err(I>1e-3)"] = max_rel;
}

void BM_reference_shader(benchmark::State& state) {
    const inputs& d = data();
    std::vector<float> out(kItems);
    for (auto _ : state) {
        for (std::size_t i = 0; i < kItems; ++i) out[i] = reference_shader::ltc_evaluate(d.m_inv[i], d.quad[i].data(), true);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
    report_errors(state, out);
}

template <typename Policy>
void BM_library_scalar(benchmark::State& state) {
    const inputs& d = data();
    std::vector<float> out(kItems);
    for (auto _ : state) {
        for (std::size_t i = 0; i < kItems; ++i)
            out[i] = ltc::transformed<ltc::clamped_cosine<float, Policy>>::from_inverse(d.m_inv[i]).integrate(
                d.quad[i].data(), 4, ltc::sidedness::two_sided);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
    report_errors(state, out);
}

template <typename Policy, ltc::batch::isa Isa>
void BM_batch_quads(benchmark::State& state) {
    if (!ltc::batch::available(Isa)) {
        state.SkipWithError("instruction set not available on this CPU");
        return;
    }
    const auto soa = data().soa();
    std::vector<float> out(kItems);
    for (auto _ : state) {
        ltc::batch::integrate_quads<Policy>(soa, out.data(), kItems, ltc::sidedness::two_sided, Isa);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
    report_errors(state, out);
}

// The runtime-n entry point on the same quads (the edge loop is not unrolled).
void BM_batch_ngons_runtime_n(benchmark::State& state) {
    const inputs& d = data();
    const auto quad = d.soa();
    const float* xs[4] = {quad.x[0], quad.x[1], quad.x[2], quad.x[3]};
    const float* ys[4] = {quad.y[0], quad.y[1], quad.y[2], quad.y[3]};
    const float* zs[4] = {quad.z[0], quad.z[1], quad.z[2], quad.z[3]};
    ltc::batch::ngon_soa<float> soa;
    soa.m_inv = quad.m_inv;
    soa.n = 4;
    soa.x = xs, soa.y = ys, soa.z = zs;
    std::vector<float> out(kItems);
    for (auto _ : state) {
        ltc::batch::integrate_ngons(soa, out.data(), kItems, ltc::sidedness::two_sided);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
    report_errors(state, out);
}

// One shared M^-1 (the first configuration's) for all items: throughput only (the errors are
// against the per-item exact values, so they are not reported).
void BM_batch_quads_shared_matrix(benchmark::State& state) {
    auto soa = data().soa();
    soa.m_inv = ltc::batch::matrices<float>::same_for_all(data().m_inv[0]);
    std::vector<float> out(kItems);
    for (auto _ : state) {
        ltc::batch::integrate_quads(soa, out.data(), kItems, ltc::sidedness::two_sided);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
}

}  // namespace

using ltc::batch::isa;
using ltc::edge_policy::minimax_rational;
BENCHMARK(BM_reference_shader);
BENCHMARK_TEMPLATE(BM_library_scalar, ltc::edge_policy::exact);
BENCHMARK_TEMPLATE(BM_library_scalar, minimax_rational);
BENCHMARK_TEMPLATE(BM_library_scalar, ltc::edge_policy::polynomial);
BENCHMARK_TEMPLATE(BM_batch_quads, minimax_rational, isa::automatic);
BENCHMARK_TEMPLATE(BM_batch_quads, minimax_rational, isa::baseline);
BENCHMARK_TEMPLATE(BM_batch_quads, minimax_rational, isa::avx2);
BENCHMARK_TEMPLATE(BM_batch_quads, minimax_rational, isa::avx512);
BENCHMARK_TEMPLATE(BM_batch_quads, ltc::edge_policy::polynomial, isa::automatic);
BENCHMARK_TEMPLATE(BM_batch_quads, minimax_rational, isa::scalar);
BENCHMARK(BM_batch_ngons_runtime_n);
BENCHMARK(BM_batch_quads_shared_matrix);

LTC_BENCHMARK_MAIN();
