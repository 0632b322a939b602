// Textured quad lights (ltc/shading/textured_light.hpp): the cost of one textured integral
// int_quad L D by each method, side by side with its error, in float and double:
//   fetch        ltc::integrate_textured_quad(d, quad, tex, side, policy) with the default policy:
//                the paper's I_D I_L, one polygon integral and one trilinear fetch of the
//                prefiltered texture (BM_plain_fetch_float: the overload without a policy, the
//                same computation without the method switch);
//   quick_cells  policy.method = quick_cells (ltc/shading/quick_cells.hpp): the 16 cells two
//                levels below the root in one batch call, up to 8 of their children in a second,
//                plus the fetch's parameters and a fetch per wide leaf holding a quarter of I_D;
//   exact_cells  policy.method = exact_cells with budget.max_cells = 64;
// and the whole shading call ltc::shade_textured_quad_light (frame, GGX table fetch, specular and
// diffuse textured integrals) by each method, in float (BM_shade).
//
// Configurations: the grid of the textured error report (tools/textured_error_report): the
// shading point at the origin, N = +z, V = (sin theta_v, 0, cos theta_v); lobes diffuse (M = I)
// and GGX at roughness 0.1, 0.25, 0.5, 1 (ltc::ggx::fetch's M^-1); theta_v = 0, 30, 60, 80 degrees;
// a 1 x 1 light centred at distance 0.5, 1.5, 4 along elevation 45 deg on the mirror side, facing
// the point, tilted by 60 deg, or vertical. Those with I_D < 1e-4 (in double) are skipped: 177
// of the 180 integrals remain; BM_shade takes the 144 GGX ones (its diffuse term is the M = I
// lobe) and keeps the 141 whose specular I_D >= 1e-4 (F0 = 0.04, albedo (0.8, 0.6, 0.4)).
// Textures, 64 x 64: "smooth" (the report's gradient (u, v, 1 - u v)) and "bright" (the report's
// bright detail: 0.02 background, a 3 x 3-texel patch of (100, 80, 60), 17% of the energy in 0.2%
// of the area). One iteration evaluates every configuration; an item is one configuration
// (SetItemsProcessed), so time_per_item (CPU time) is the cost of one textured integral, or of
// one shading call.
//
// Counters, so that cost and error sit side by side:
//   mean_rel_err, max_rel_err  |sum_rgb(value) - sum_rgb(ref)| / sum_rgb(ref) over the
//       configurations, ref the full-refinement exact_cells value of the same configuration in
//       double (budget 4096 >= the texel count: the exact integral of the texel-constant texture,
//       up to rounding; for BM_shade, shade_textured_quad_light with that policy, specular +
//       diffuse): the texture the report's Monte Carlo also integrates, without its noise; it
//       includes float rounding for float.
//   integrals  polygon integrals per item (the cells' `integrals` field; 1 per fetch).
//
// Run: ./build/benchmarks/bench_textured --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true --benchmark_enable_random_interleaving=true
// and compare medians; the ratio of two methods' time_per_item is meaningful within one run.
#include "bench_main.hpp"
#include "textured_placements.hpp"

#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/light_texture.hpp>
#include <ltc/shading/quick_cells.hpp>
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/textured_cells.hpp>
#include <ltc/shading/textured_light.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using namespace bench_textured;

// The integral configurations: every placement with I_D >= 1e-4 (in double).
template <typename T>
struct integral_config {
    ltc::transformed<ltc::clamped_cosine<T>> d;
    std::array<glm::vec<3, T>, 4> quad;
    glm::dvec3 ref[2];  // full-refinement exact_cells in double, per texture
};

template <typename T>
const std::vector<integral_config<T>>& integral_configs() {
    static const std::vector<integral_config<T>> v = [] {
        std::vector<integral_config<T>> out;
        ltc::textured_policy full;
        full.method = ltc::textured_method::exact_cells;
        full.budget.max_cells = kFullBudget;
        for (const placement& p : placements()) {
            const auto dd = lobe<double>(p);
            if (!(dd.integrate(p.quad, 4) >= 1e-4)) continue;
            integral_config<T> c{lobe<T>(p), {}, {}};
            for (int k = 0; k < 4; ++k) c.quad[std::size_t(k)] = glm::vec<3, T>(p.quad[k]);
            for (int t = 0; t < 2; ++t)
                c.ref[t] = ltc::integrate_textured_quad(dd, p.quad, texture<double>(texture_id(t)), ltc::sidedness::two_sided, full);
            out.push_back(c);
        }
        return out;
    }();
    return v;
}

// The shading configurations: the GGX placements (roughness 0.1 - 1) whose specular I_D >= 1e-4.
struct shading_config {
    glm::vec3 V;
    float roughness;
    std::array<glm::vec3, 4> quad;
    glm::dvec3 V_d;
    std::array<glm::dvec3, 4> quad_d;
    double ref[2];  // sum_rgb(specular + diffuse), full-refinement exact_cells in double, per texture
};

const glm::dvec3 kF0(0.04), kAlbedo(0.8, 0.6, 0.4);

ltc::textured_light_result<double> shade_double(const shading_config& c, texture_id t, const ltc::textured_policy& policy) {
    return ltc::shade_textured_quad_light(glm::dvec3(0), glm::dvec3(0, 0, 1), c.V_d, double(c.roughness), kF0, kAlbedo,
                                          c.quad_d.data(), texture<double>(t), ltc::sidedness::two_sided, policy);
}

const std::vector<shading_config>& shading_configs() {
    static const std::vector<shading_config> v = [] {
        std::vector<shading_config> out;
        ltc::textured_policy full;
        full.method = ltc::textured_method::exact_cells;
        full.budget.max_cells = kFullBudget;
        for (const placement& p : placements()) {
            if (p.roughness < 0 || !(lobe<double>(p).integrate(p.quad, 4) >= 1e-4)) continue;
            shading_config c;
            c.V_d = glm::dvec3(std::sin(p.theta_v), 0, std::cos(p.theta_v));
            c.V = glm::vec3(c.V_d);
            c.roughness = float(p.roughness);
            for (std::size_t k = 0; k < 4; ++k) c.quad_d[k] = p.quad[k], c.quad[k] = glm::vec3(p.quad[k]);
            for (int t = 0; t < 2; ++t) {
                const auto r = shade_double(c, texture_id(t), full);
                const glm::dvec3 s = r.specular + r.diffuse;
                c.ref[t] = s.x + s.y + s.z;
            }
            out.push_back(c);
        }
        return out;
    }();
    return v;
}

ltc::textured_policy policy_of(ltc::textured_method m) {
    ltc::textured_policy p;
    p.method = m;
    p.budget.max_cells = 64;  // exact_cells only; quick_cells uses textured_policy::quick_cells_budget
    return p;
}

void report(benchmark::State& state, std::size_t items, const std::vector<double>& value, const std::vector<double>& ref,
            double integrals) {
    double sum = 0, worst = 0;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const double e = std::abs(value[i] - ref[i]) / ref[i];
        sum += e;
        worst = std::max(worst, e);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * items));
    // CPU seconds per item (printed with its SI prefix, e.g. 146.1ns).
    state.counters["time_per_item"] =
        benchmark::Counter(double(items), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["mean_rel_err"] = sum / double(value.size());
    state.counters["max_rel_err"] = worst;
    state.counters["integrals"] = integrals;
}

// The polygon integrals of one textured integral by a cell method (exact_cells with 64 cells).
template <typename T>
std::size_t cell_integrals(ltc::textured_method m, const ltc::transformed<ltc::clamped_cosine<T>>& d,
                           const glm::vec<3, T>* quad, const ltc::light_texture<T>& tex) {
    if (m == ltc::textured_method::quick_cells) return ltc::integrate_quick_cells(d, quad, tex).integrals;
    ltc::cell_budget b;
    b.max_cells = 64;
    return ltc::integrate_textured_cells(d, quad, tex.cells(), ltc::sidedness::two_sided, b).integrals;
}

// The polygon integrals one textured integral costs, averaged over the configurations.
template <typename T>
double mean_integrals(ltc::textured_method m, texture_id t) {
    if (m == ltc::textured_method::fetch) return 1;
    double n = 0;
    for (const auto& c : integral_configs<T>())
        n += double(cell_integrals(m, c.d, c.quad.data(), texture<T>(t)));
    return n / double(integral_configs<T>().size());
}

// report() for the integrals out[i] of configs[i], against their references for texture t.
template <typename T>
void report_integrals(benchmark::State& state, const std::vector<integral_config<T>>& configs,
                      const std::vector<glm::vec<3, T>>& out, texture_id t, double integrals) {
    std::vector<double> value, ref;
    for (std::size_t i = 0; i < configs.size(); ++i) {
        value.push_back(double(out[i].x) + double(out[i].y) + double(out[i].z));
        ref.push_back(configs[i].ref[t].x + configs[i].ref[t].y + configs[i].ref[t].z);
    }
    report(state, configs.size(), value, ref, integrals);
}

template <typename T>
void BM_integral(benchmark::State& state, ltc::textured_method method, texture_id t) {
    const auto& configs = integral_configs<T>();
    const auto& tex = texture<T>(t);
    const ltc::textured_policy policy = policy_of(method);
    std::vector<glm::vec<3, T>> out(configs.size());
    for (auto _ : state) {
        for (std::size_t i = 0; i < configs.size(); ++i)
            out[i] = ltc::integrate_textured_quad(configs[i].d, configs[i].quad.data(), tex, ltc::sidedness::two_sided, policy);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    report_integrals(state, configs, out, t, mean_integrals<T>(method, t));
}

// The four-argument overload (no policy): the paper's fetch as a renderer calls it, for comparison
// with the policy overload's fetch (the switch).
template <typename T>
void BM_integral_plain_fetch(benchmark::State& state, texture_id t) {
    const auto& configs = integral_configs<T>();
    const auto& tex = texture<T>(t);
    std::vector<glm::vec<3, T>> out(configs.size());
    for (auto _ : state) {
        for (std::size_t i = 0; i < configs.size(); ++i)
            out[i] = ltc::integrate_textured_quad(configs[i].d, configs[i].quad.data(), tex, ltc::sidedness::two_sided);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    report_integrals(state, configs, out, t, 1);
}

// The polygon integrals one shading call costs (specular and diffuse), averaged over the
// configurations: the calls of shade_textured_quad_light repeated (frame, table fetch, lobes).
double mean_shading_integrals(ltc::textured_method m, texture_id t) {
    if (m == ltc::textured_method::fetch) return 2;
    const auto cosine = ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(glm::mat3(1.0f));
    double n = 0;
    for (const shading_config& c : shading_configs()) {
        const auto frame = ltc::make_shading_frame(glm::vec3(0, 0, 1), c.V);
        glm::vec3 local[4];
        for (std::size_t k = 0; k < 4; ++k) local[k] = frame.to_local(c.quad[k]);
        const auto spec = ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(
            ltc::ggx::fetch<float>(frame.cos_theta_v, c.roughness).m_inv);
        for (const auto* d : {&spec, &cosine})
            n += double(cell_integrals(m, *d, local, texture<float>(t)));
    }
    return n / double(shading_configs().size());
}

void BM_shade(benchmark::State& state, ltc::textured_method method, texture_id t) {
    const auto& configs = shading_configs();
    const auto& tex = texture<float>(t);
    const ltc::textured_policy policy = policy_of(method);
    const glm::vec3 P(0), N(0, 0, 1), F0(kF0), albedo(kAlbedo);
    std::vector<ltc::textured_light_result<float>> out(configs.size());
    for (auto _ : state) {
        for (std::size_t i = 0; i < configs.size(); ++i)
            out[i] = ltc::shade_textured_quad_light(P, N, configs[i].V, configs[i].roughness, F0, albedo,
                                                    configs[i].quad.data(), tex, ltc::sidedness::two_sided, policy);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    std::vector<double> value, ref;
    for (std::size_t i = 0; i < configs.size(); ++i) {
        const glm::dvec3 s = glm::dvec3(out[i].specular) + glm::dvec3(out[i].diffuse);
        value.push_back(s.x + s.y + s.z);
        ref.push_back(configs[i].ref[t]);
    }
    report(state, configs.size(), value, ref, mean_shading_integrals(method, t));
}

// BENCHMARK_CAPTURE pastes the function's name into an identifier: no template arguments there.
void BM_integral_float(benchmark::State& state, ltc::textured_method m, texture_id t) { BM_integral<float>(state, m, t); }
void BM_integral_double(benchmark::State& state, ltc::textured_method m, texture_id t) { BM_integral<double>(state, m, t); }
void BM_plain_fetch_float(benchmark::State& state, texture_id t) { BM_integral_plain_fetch<float>(state, t); }

}  // namespace

using ltc::textured_method;

BENCHMARK_CAPTURE(BM_plain_fetch_float, smooth, smooth);
BENCHMARK_CAPTURE(BM_integral_float, fetch_smooth, textured_method::fetch, smooth);
BENCHMARK_CAPTURE(BM_integral_float, quick_cells_smooth, textured_method::quick_cells, smooth);
BENCHMARK_CAPTURE(BM_integral_float, exact_cells_64_smooth, textured_method::exact_cells, smooth);
BENCHMARK_CAPTURE(BM_plain_fetch_float, bright, bright);
BENCHMARK_CAPTURE(BM_integral_float, fetch_bright, textured_method::fetch, bright);
BENCHMARK_CAPTURE(BM_integral_float, quick_cells_bright, textured_method::quick_cells, bright);
BENCHMARK_CAPTURE(BM_integral_float, exact_cells_64_bright, textured_method::exact_cells, bright);
BENCHMARK_CAPTURE(BM_integral_double, fetch_smooth, textured_method::fetch, smooth);
BENCHMARK_CAPTURE(BM_integral_double, quick_cells_smooth, textured_method::quick_cells, smooth);
BENCHMARK_CAPTURE(BM_integral_double, exact_cells_64_smooth, textured_method::exact_cells, smooth);
BENCHMARK_CAPTURE(BM_integral_double, fetch_bright, textured_method::fetch, bright);
BENCHMARK_CAPTURE(BM_integral_double, quick_cells_bright, textured_method::quick_cells, bright);
BENCHMARK_CAPTURE(BM_integral_double, exact_cells_64_bright, textured_method::exact_cells, bright);
BENCHMARK_CAPTURE(BM_shade, fetch_smooth, textured_method::fetch, smooth);
BENCHMARK_CAPTURE(BM_shade, quick_cells_smooth, textured_method::quick_cells, smooth);
BENCHMARK_CAPTURE(BM_shade, exact_cells_64_smooth, textured_method::exact_cells, smooth);
BENCHMARK_CAPTURE(BM_shade, fetch_bright, textured_method::fetch, bright);
BENCHMARK_CAPTURE(BM_shade, quick_cells_bright, textured_method::quick_cells, bright);
BENCHMARK_CAPTURE(BM_shade, exact_cells_64_bright, textured_method::exact_cells, bright);

LTC_BENCHMARK_MAIN();
