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
//
// Shading batches (BM_shade_*, BM_old_*): ltc::batch::shade<Model> (ltc/shading/batch_shade.hpp)
// side by side with the deprecated batch names that do the same (one light over 4096 points:
// shade_polygon_light_one_lobe, shade_polygon_light = _cosine_lobe, _two_lobe; 4096 quad lights
// over one point: shade_quad_lights_one_lobe, shade_quad_lights, _two_lobe), over the scene of
// bench_shading.cpp (a 64 x 64 grid on a floor, one tilted quad light crossing the horizon of part
// of it), and batch::shade with F0 and albedo uniform (batch::uniform) where the old names need
// an array per channel. Throughput only: the results are the same bits (tests/test_batch_shade.cpp).
#include "bench_main.hpp"
#include "configurations.hpp"
#include "reference_shader.hpp"

#include <ltc/reference/splitmix64.hpp>
#include <ltc/shading/batch.hpp>
#include <ltc/shading/batch_cosine_lobe.hpp>
#include <ltc/shading/batch_shade.hpp>
#include <ltc/shading/batch_shading.hpp>
#include <ltc/shading/batch_two_lobe.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <type_traits>
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

// The shading scene of bench_shading.cpp: 4096 points on the floor z = 0, normals tilted up to 30
// degrees, seen from (0, -4, 2), roughness varying, F0 = 0.04 and albedo (0.8, 0.6, 0.4) for all;
// a 1.5 x 0.8 quad at height 1.2 tilted by 60 degrees; for the lights batches, 4096 copies of it
// moved about, shading the grid's centre.
struct shading_scene {
    std::vector<float> a[16];  // px py pz nx ny nz vx vy vz roughness f0 rgb albedo rgb
    glm::vec3 light[4];
    glm::vec3 radiance{4.0f, 3.5f, 3.0f};
    std::vector<float> lx[4], ly[4], lz[4], lr[3];

    shading_scene() {
        ltc::ground_truth::splitmix64 g(2016);
        const glm::vec3 eye(0, -4, 2);
        for (std::size_t i = 0; i < kItems; ++i) {
            const glm::vec3 P(-2 + 4 * float(i % 64) / 63, -2 + 4 * float(i / 64) / 63, 0);
            const float tilt = 0.52f * float(g.uniform()), phi = 6.2831853f * float(g.uniform());
            const glm::vec3 N(std::sin(tilt) * std::cos(phi), std::sin(tilt) * std::sin(phi), std::cos(tilt));
            const glm::vec3 V = eye - P;
            const float v[16] = {P.x, P.y, P.z, N.x, N.y, N.z, V.x, V.y, V.z, 0.05f + 0.95f * float(g.uniform()),
                                 0.04f, 0.04f, 0.04f, 0.8f, 0.6f, 0.4f};
            for (int c = 0; c < 16; ++c) a[c].push_back(v[c]);
        }
        const glm::vec3 centre(0.3f, 0.5f, 1.2f), ex(0.75f, 0, 0), ey(0, 0.4f * 0.5f, 0.4f * 0.866f);
        light[0] = centre - ex - ey, light[1] = centre + ex - ey;
        light[2] = centre + ex + ey, light[3] = centre - ex + ey;
        ltc::ground_truth::splitmix64 h(7);
        for (std::size_t j = 0; j < kItems; ++j) {
            const glm::vec3 shift(float(h.uniform()) - 0.5f, float(h.uniform()) - 0.5f, 0.5f * float(h.uniform()));
            for (int k = 0; k < 4; ++k) {
                const glm::vec3 p = light[k] + shift;
                lx[k].push_back(p.x), ly[k].push_back(p.y), lz[k].push_back(p.z);
            }
            for (int c = 0; c < 3; ++c) lr[c].push_back(radiance[c]);
        }
    }
    glm::vec3 vec(int c, std::size_t i) const { return glm::vec3(a[c][i], a[c + 1][i], a[c + 2][i]); }
    ltc::batch::shading_points<float> points() const {
        const float* c[16];
        for (int k = 0; k < 16; ++k) c[k] = a[k].data();
        return ltc::batch::shading_points<float>::from_columns(c);
    }
    ltc::batch::surfaces<float> surfaces(bool uniform_colours) const {
        ltc::batch::surfaces<float> s{kItems,
                                      {a[0].data(), a[1].data(), a[2].data()},
                                      {a[3].data(), a[4].data(), a[5].data()},
                                      {a[6].data(), a[7].data(), a[8].data()},
                                      a[9].data(),
                                      {a[10].data(), a[11].data(), a[12].data()},
                                      {a[13].data(), a[14].data(), a[15].data()}};
        if (uniform_colours)
            s.f0 = ltc::batch::uniform(0.04f), s.albedo = ltc::batch::uniform(glm::vec3(0.8f, 0.6f, 0.4f));
        return s;
    }
    ltc::batch::quad_lights<float> quads() const {
        ltc::batch::quad_lights<float> q;
        for (int k = 0; k < 4; ++k) q.x[k] = lx[k].data(), q.y[k] = ly[k].data(), q.z[k] = lz[k].data();
        for (int c = 0; c < 3; ++c) q.radiance[c] = lr[c].data();
        return q;
    }
    // Two-sided, or one-sided towards an emission normal (down, the floor's side: each light's
    // walking order found from its vector area).
    ltc::batch::polygon_lights<float> polygon_lights(bool emission_normal) const {
        const float* xs[4] = {lx[0].data(), lx[1].data(), lx[2].data(), lx[3].data()};
        const float* ys[4] = {ly[0].data(), ly[1].data(), ly[2].data(), ly[3].data()};
        const float* zs[4] = {lz[0].data(), lz[1].data(), lz[2].data(), lz[3].data()};
        if (emission_normal)
            return ltc::batch::polygon_lights<float>::one_sided(
                kItems, xs, ys, zs, ltc::batch::uniform(glm::vec3(0, 0, -1)), ltc::batch::uniform(radiance));
        return ltc::batch::polygon_lights<float>::two_sided(kItems, xs, ys, zs, ltc::batch::uniform(radiance));
    }
    ltc::surface<float> centre() const {
        const std::size_t i = 32 * 64 + 32;
        return {vec(0, i), vec(3, i), vec(6, i), a[9][i], vec(10, i), vec(13, i)};
    }
};

const shading_scene& the_scene() {
    static const shading_scene s;
    return s;
}

struct shading_outputs {
    std::vector<float> c[6];
    shading_outputs() {
        for (auto& v : c) v.resize(kItems);
    }
    ltc::batch::shading_results<float> results() {
        ltc::batch::shading_results<float> r;
        for (int k = 0; k < 3; ++k) r.specular[k] = c[k].data(), r.diffuse[k] = c[3 + k].data();
        return r;
    }
};

// The deprecated name of Model's batch over many points (two-sided quad, the old sidedness).
template <typename Model>
void old_points(const shading_scene& s, const ltc::batch::shading_results<float>& out, ltc::batch::isa which) {
    const auto p = s.points();
    const auto two = ltc::sidedness::two_sided;
    if constexpr (std::is_same_v<Model, ltc::ggx::one_lobe>)
        ltc::batch::shade_polygon_light_one_lobe(p, s.radiance, s.light, 4, two, out, kItems, which);
    else if constexpr (std::is_same_v<Model, ltc::ggx::two_lobes>)
        ltc::batch::shade_polygon_light_two_lobe(p, s.radiance, s.light, 4, two, out, kItems, which);
    else
        ltc::batch::shade_polygon_light(p, s.radiance, s.light, 4, two, out, kItems, which);
}

template <typename Model, ltc::batch::isa Which = ltc::batch::isa::automatic>
void BM_old_points(benchmark::State& state) {
    const shading_scene& s = the_scene();
    shading_outputs out;
    const auto results = out.results();
    for (auto _ : state) {
        old_points<Model>(s, results, Which);
        benchmark::DoNotOptimize(out.c[0].data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
}

// batch::shade<Model> over the points; Uniform: F0 and albedo uniform instead of six arrays.
template <typename Model, bool Uniform = false, ltc::batch::isa Which = ltc::batch::isa::automatic>
void BM_shade_points(benchmark::State& state) {
    const shading_scene& s = the_scene();
    const auto points = s.surfaces(Uniform);
    const auto light = ltc::polygon_light<float>::two_sided(s.light, 4, s.radiance);
    shading_outputs out;
    const auto results = out.results();
    for (auto _ : state) {
        ltc::batch::shade<Model>(points, light, results, Which);
        benchmark::DoNotOptimize(out.c[0].data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
}

template <typename Model>
void BM_old_quad_lights(benchmark::State& state) {
    const shading_scene& s = the_scene();
    const auto q = s.quads();
    const auto c = s.centre();
    shading_outputs out;
    const auto results = out.results();
    const auto two = ltc::sidedness::two_sided;
    for (auto _ : state) {
        if constexpr (std::is_same_v<Model, ltc::ggx::one_lobe>)
            ltc::batch::shade_quad_lights_one_lobe(c.position, c.normal, c.view, c.roughness, c.f0, c.albedo, q, two,
                                                   results, kItems);
        else if constexpr (std::is_same_v<Model, ltc::ggx::two_lobes>)
            ltc::batch::shade_quad_lights_two_lobe(c.position, c.normal, c.view, c.roughness, c.f0, c.albedo, q, two,
                                                   results, kItems);
        else
            ltc::batch::shade_quad_lights(c.position, c.normal, c.view, c.roughness, c.f0, c.albedo, q, two, results,
                                          kItems);
        benchmark::DoNotOptimize(out.c[0].data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
}

// batch::shade<Model> over polygon_lights, the radiance uniform; two-sided as the old rows, or
// one-sided towards an emission normal.
template <typename Model, bool EmissionNormal = false>
void BM_shade_lights(benchmark::State& state) {
    const shading_scene& s = the_scene();
    const auto lights = s.polygon_lights(EmissionNormal);
    const auto c = s.centre();
    shading_outputs out;
    const auto results = out.results();
    for (auto _ : state) {
        ltc::batch::shade<Model>(c, lights, results);
        benchmark::DoNotOptimize(out.c[0].data());
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
using ltc::ggx::one_lobe;
using ltc::ggx::ltc_and_cosine;
using ltc::ggx::two_lobes;
BENCHMARK_TEMPLATE(BM_old_points, one_lobe);
BENCHMARK_TEMPLATE(BM_shade_points, one_lobe);
BENCHMARK_TEMPLATE(BM_shade_points, one_lobe, true);
BENCHMARK_TEMPLATE(BM_old_points, ltc_and_cosine);
BENCHMARK_TEMPLATE(BM_shade_points, ltc_and_cosine);
BENCHMARK_TEMPLATE(BM_shade_points, ltc_and_cosine, true);
BENCHMARK_TEMPLATE(BM_old_points, two_lobes);
BENCHMARK_TEMPLATE(BM_shade_points, two_lobes);
BENCHMARK_TEMPLATE(BM_shade_points, two_lobes, true);
BENCHMARK_TEMPLATE(BM_old_points, ltc_and_cosine, isa::avx2);
BENCHMARK_TEMPLATE(BM_shade_points, ltc_and_cosine, false, isa::avx2);
BENCHMARK_TEMPLATE(BM_old_points, ltc_and_cosine, isa::baseline);
BENCHMARK_TEMPLATE(BM_shade_points, ltc_and_cosine, false, isa::baseline);
BENCHMARK_TEMPLATE(BM_old_quad_lights, one_lobe);
BENCHMARK_TEMPLATE(BM_shade_lights, one_lobe);
BENCHMARK_TEMPLATE(BM_old_quad_lights, ltc_and_cosine);
BENCHMARK_TEMPLATE(BM_shade_lights, ltc_and_cosine);
BENCHMARK_TEMPLATE(BM_shade_lights, ltc_and_cosine, true);
BENCHMARK_TEMPLATE(BM_old_quad_lights, two_lobes);
BENCHMARK_TEMPLATE(BM_shade_lights, two_lobes);

LTC_BENCHMARK_MAIN();
