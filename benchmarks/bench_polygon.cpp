// Polygon-light integral: the reference shader path (ported in reference_shader.hpp) against the
// library's exact clipped integral, per edge policy, in float and double. Each benchmark runs over
// the same 4096 random configurations (GGX-like M^-1, a quad crossing the horizon in ~half of
// them) and reports ns per evaluation and, as counters, the maximum absolute and relative error
// against the library's double-precision exact closed form.
#include "bench_main.hpp"
#include "configurations.hpp"
#include "reference_shader.hpp"

#include <ltc/shading/clipless.hpp>
#include <ltc/ltc.hpp>
#include <ltc/shading/polygon_light.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace {

using bench::config;
using bench::configs;

double exact(const config& c) {
    return ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(c.m_inv).integrate(c.quad, 4, ltc::sidedness::two_sided);
}

template <typename F>
void report_errors(benchmark::State& state, F f) {
    double max_abs = 0, max_rel = 0;
    for (const config& c : configs()) {
        const double e = exact(c), v = f(c), err = std::abs(v - e);
        max_abs = std::max(max_abs, err);
        if (e > 1e-3) max_rel = std::max(max_rel, err / e);
    }
    state.counters["max_abs_err"] = max_abs;
    state.counters["max_rel_err(I>1e-3)"] = max_rel;
}

template <typename T>
struct typed_config {
    glm::mat<3, 3, T> m_inv;
    glm::vec<3, T> quad[4];
};

template <typename T>
const std::vector<typed_config<T>>& typed_configs() {
    static const std::vector<typed_config<T>> all = [] {
        std::vector<typed_config<T>> v;
        for (const config& c : configs()) {
            typed_config<T> t;
            t.m_inv = glm::mat<3, 3, T>(c.m_inv);
            for (int i = 0; i < 4; ++i) t.quad[i] = glm::vec<3, T>(c.quad[i]);
            v.push_back(t);
        }
        return v;
    }();
    return all;
}

void BM_reference_shader(benchmark::State& state) {
    const auto& cs = typed_configs<float>();
    std::size_t i = 0;
    for (auto _ : state) {
        const auto& c = cs[i++ & 4095];
        benchmark::DoNotOptimize(reference_shader::ltc_evaluate(c.m_inv, c.quad, true));
    }
    state.SetItemsProcessed(state.iterations());
    report_errors(state, [](const config& c) {
        glm::vec3 q[4];
        for (int k = 0; k < 4; ++k) q[k] = glm::vec3(c.quad[k]);
        return static_cast<double>(reference_shader::ltc_evaluate(glm::mat3(c.m_inv), q, true));
    });
    // What the configurations ask of a clipper (float, as evaluated): the share of quads crossing
    // the horizon, and the clipped edges, of which those with a negative cosine.
    double crossing = 0, edges = 0, negative = 0;
    for (const auto& c : typed_configs<float>()) {
        int above = 0;
        for (const auto& p : c.quad) above += (c.m_inv * p).z >= 0.0f ? 1 : 0;
        crossing += above > 0 && above < 4 ? 1 : 0;
        ltc::detail::for_each_unit_edge<float, true>(
            ltc::detail::transformed_vertices<float>{c.m_inv, c.quad}, 4,
            [&](const glm::vec3& a, const glm::vec3& b, const glm::vec3&) {
                edges += 1;
                negative += glm::dot(a, b) < 0.0f ? 1 : 0;
            });
    }
    state.counters["crossing_quads"] = crossing / 4096;
    state.counters["clipped_edges"] = edges;
    state.counters["negative_cosine_edges"] = negative;
}

template <typename T, typename Policy>
T library(const typed_config<T>& c) {
    return ltc::transformed<ltc::clamped_cosine<T, Policy>>::from_inverse(c.m_inv).integrate(c.quad, 4, ltc::sidedness::two_sided);
}

template <typename T, typename Policy>
void BM_library(benchmark::State& state) {
    const auto& cs = typed_configs<T>();
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(library<T, Policy>(cs[i++ & 4095]));
    state.SetItemsProcessed(state.iterations());
    report_errors(state, [](const config& c) {
        typed_config<T> t;
        t.m_inv = glm::mat<3, 3, T>(c.m_inv);
        for (int k = 0; k < 4; ++k) t.quad[k] = glm::vec<3, T>(c.quad[k]);
        return static_cast<double>(library<T, Policy>(t));
    });
}

// The README's first integral, transformed<clamped_cosine<float>> with the default edge policy,
// through each documented entry point: integrate(q, 4) (two-sided by default) and
// integrate(q, 4, sidedness), next to BM_reference_shader so that their ratio comes from one run.
enum class entry { two_arguments, two_sided };

template <entry E>
float readme_integral(const typed_config<float>& c) {
    const auto d = ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(c.m_inv);
    if constexpr (E == entry::two_arguments) return d.integrate(c.quad, 4);
    if constexpr (E == entry::two_sided) return d.integrate(c.quad, 4, ltc::sidedness::two_sided);
}

template <entry E>
void BM_readme_integral(benchmark::State& state) {
    const auto& cs = typed_configs<float>();
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(readme_integral<E>(cs[i++ & 4095]));
    state.SetItemsProcessed(state.iterations());
    report_errors(state, [](const config& c) {
        typed_config<float> t;
        t.m_inv = glm::mat3(c.m_inv);
        for (int k = 0; k < 4; ++k) t.quad[k] = glm::vec3(c.quad[k]);
        return static_cast<double>(readme_integral<E>(t));
    });
}

// Cost of the steps of the library's quad path: everything but the fit of theta / sin(theta),
// with a policy whose factor is 1 (transform, clip, normalization, the edges' cosines and cross
// products, the branch on the sign of the cosine), against the full path with each policy.
struct unit_factor {
    template <typename T>
    static T positive_branch(T) { return T(1); }
    template <typename T>
    static T theta_over_sin(T, const glm::vec<3, T>&) { return T(1); }
};

void BM_step_without_fit(benchmark::State& state) {
    const auto& cs = typed_configs<float>();
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(library<float, unit_factor>(cs[i++ & 4095]));
}

// The edge terms alone, on the 4 edges of the transformed quads' unit vertices (unclipped,
// precomputed): the reference shader's integrate_edge_vec against each policy's edge_integral_z.
const std::vector<std::array<glm::vec3, 4>>& unit_quads() {
    static const std::vector<std::array<glm::vec3, 4>> all = [] {
        std::vector<std::array<glm::vec3, 4>> v;
        for (const auto& c : typed_configs<float>()) {
            const ltc::detail::transformed_vertices<float> at{c.m_inv, c.quad};
            v.push_back({at(0), at(1), at(2), at(3)});
        }
        return v;
    }();
    return all;
}

// The edge term of a policy, or (Policy = reference_edge) the reference shader's.
struct reference_edge {};
template <typename Policy>
float edge_z(const glm::vec3& a, const glm::vec3& b) {
    if constexpr (std::is_same_v<Policy, reference_edge>)
        return reference_shader::integrate_edge_vec(a, b).z;
    else
        return ltc::edge_integral_z<Policy>(a, b);
}

template <typename Policy>
void BM_step_edges(benchmark::State& state) {
    const auto& us = unit_quads();
    std::size_t i = 0;
    for (auto _ : state) {
        const auto& u = us[i++ & 4095];
        float sum = 0;
        for (std::size_t k = 0; k < 4; ++k) sum += edge_z<Policy>(u[k], u[(k + 1) & 3]);
        benchmark::DoNotOptimize(sum);
    }
}

// (c) the clipless sphere approximation (Hill 2016), analytic or tabulated, its vector form
// factor's edge terms by Policy. Its error against the exact clipped integral is that of the
// approximation itself.
template <typename T, ltc::clipless::method How, typename Policy>
T clipless_path(const typed_config<T>& c) {
    return ltc::clipless::integrate(ltc::transformed<ltc::clamped_cosine<T, Policy>>::from_inverse(c.m_inv), c.quad,
                                    4, ltc::sidedness::two_sided, How);
}

template <typename T, ltc::clipless::method How, typename Policy>
void BM_clipless(benchmark::State& state) {
    const auto& cs = typed_configs<T>();
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(clipless_path<T, How, Policy>(cs[i++ & 4095]));
    state.SetItemsProcessed(state.iterations());
    report_errors(state, [](const config& c) {
        typed_config<T> t;
        t.m_inv = glm::mat<3, 3, T>(c.m_inv);
        for (int k = 0; k < 4; ++k) t.quad[k] = glm::vec<3, T>(c.quad[k]);
        return static_cast<double>(clipless_path<T, How, Policy>(t));
    });
}

// (d) full GGX shading of a quad light in world space: frame, table fetch, specular + diffuse.
// Its error counters compare with the same shading in double (the closed forms and the table
// lookup in double): the precision the float path loses, not the LTC approximation's own error
// (for that, see ggx_error_report's Monte Carlo ground truth).
template <typename T, typename Policy = ltc::edge_policy::exact>
ltc::polygon_light_result<T> ggx_shade(const typed_config<T>& c, std::size_t i) {
    using vec3 = glm::vec<3, T>;
    const vec3 P(0), N(0, 0, 1), F0(T(0.04)), albedo(T(0.5)), radiance(1);
    const T t = T((i & 63) + 1) / T(64);
    const vec3 V = glm::normalize(vec3(t, T(0.1), T(1)));
    return ltc::shade_polygon_light_one_lobe<Policy>(P, N, V, t, F0, albedo, radiance, c.quad, 4,
                                                     ltc::sidedness::two_sided);
}

template <typename T, typename Policy>
void BM_ggx_shading(benchmark::State& state) {
    const auto& cs = typed_configs<T>();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(ggx_shade<T, Policy>(cs[i & 4095], i));
        ++i;
    }
    state.SetItemsProcessed(state.iterations());
    double max_abs = 0, max_rel = 0;
    for (std::size_t k = 0; k < 4096; ++k) {
        const auto r = ggx_shade<T, Policy>(typed_configs<T>()[k], k);
        const auto e = ggx_shade<double>(typed_configs<double>()[k], k);
        const double v = double(r.specular.x) + double(r.diffuse.x), ref = e.specular.x + e.diffuse.x;
        max_abs = std::max(max_abs, std::abs(v - ref));
        if (ref > 1e-3) max_rel = std::max(max_rel, std::abs(v - ref) / ref);
    }
    state.counters["max_abs_err"] = max_abs;
    state.counters["max_rel_err(I>1e-3)"] = max_rel;
}

}  // namespace

BENCHMARK_TEMPLATE(BM_clipless, float, ltc::clipless::method::analytic, ltc::edge_policy::exact);
BENCHMARK_TEMPLATE(BM_clipless, float, ltc::clipless::method::analytic, ltc::edge_policy::polynomial);
BENCHMARK_TEMPLATE(BM_clipless, float, ltc::clipless::method::table, ltc::edge_policy::polynomial);
BENCHMARK_TEMPLATE(BM_clipless, double, ltc::clipless::method::analytic, ltc::edge_policy::exact);
BENCHMARK_TEMPLATE(BM_ggx_shading, float, ltc::edge_policy::exact);
BENCHMARK_TEMPLATE(BM_ggx_shading, float, ltc::edge_policy::minimax_rational);
BENCHMARK_TEMPLATE(BM_ggx_shading, double, ltc::edge_policy::exact);
BENCHMARK(BM_reference_shader);
BENCHMARK_TEMPLATE(BM_readme_integral, entry::two_arguments);
BENCHMARK_TEMPLATE(BM_readme_integral, entry::two_sided);
BENCHMARK(BM_step_without_fit);
BENCHMARK_TEMPLATE(BM_step_edges, reference_edge);
BENCHMARK_TEMPLATE(BM_step_edges, ltc::edge_policy::exact);
BENCHMARK_TEMPLATE(BM_step_edges, ltc::edge_policy::polynomial);
BENCHMARK_TEMPLATE(BM_step_edges, ltc::edge_policy::minimax_rational);
BENCHMARK_TEMPLATE(BM_step_edges, ltc::edge_policy::rational);
BENCHMARK_TEMPLATE(BM_library, float, ltc::edge_policy::exact);
BENCHMARK_TEMPLATE(BM_library, float, ltc::edge_policy::minimax_rational);
BENCHMARK_TEMPLATE(BM_library, float, ltc::edge_policy::polynomial);
BENCHMARK_TEMPLATE(BM_library, float, ltc::edge_policy::rational);
BENCHMARK_TEMPLATE(BM_library, float, ltc::edge_policy::fp16_quadratic);
BENCHMARK_TEMPLATE(BM_library, double, ltc::edge_policy::exact);
BENCHMARK_TEMPLATE(BM_library, double, ltc::edge_policy::polynomial);

LTC_BENCHMARK_MAIN();
