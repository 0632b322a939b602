// Sampling polygonal lights (ltc/core/*_sampling.hpp): what one sample costs, float and double, over the same
// 1024 shading configurations (a 1.2 x 1.2 quad light 1.2 above a floor, tilted 60 degrees so
// that it crosses the horizon of part of the points; normals tilted up to 30 degrees; the GGX
// table's lobe at each point's N.V, roughness 0.05-1):
//   projected      ltc::projected_polygon_sampler: the clamped cosine restricted to the polygon
//                  (exact; two Newton solves); counters: evals = closed-form evaluations per sample
//   ltc_polygon    ltc::ltc_polygon_sampler: the LTC restricted to the polygon (the above in the
//                  cosine's space, then M)
//   *_setup        building the sampler for a polygon (clipping, fan, per-triangle constants)
//   area           ltc::polygon_area_sampler: uniform on the light's area, with its solid-angle pdf
//   ggx_brdf       GGX visible-normal sampling with its pdf (ltc/brdf/ggx.hpp)
//   shade          ltc::shade_polygon_light_one_lobe (no shadows; the shadowed shading's default
//                  table), and shade_polygon_light_shadowed with K = 4 and 16 samples per lobe
//                  for both samplers, visibility always true (the shading's own cost, without the
//                  ray tracer's)
// time_per_item is per sample (or per polygon for *_setup, per shading call for shade_*):
//   ./build/benchmarks/bench_sampling --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//       --benchmark_enable_random_interleaving=true
#include "bench_main.hpp"

#include <ltc/core/ltc_polygon_sampling.hpp>
#include <ltc/core/polygon_area_sampling.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>
#include <ltc/brdf/ggx.hpp>
#include <ltc/reference/splitmix64.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/shadowed_polygon_light.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace {

constexpr std::size_t kItems = 1024;
constexpr std::size_t kSamplesPerItem = 16;

struct config {
    glm::vec3 P, N, V;
    float roughness;
    glm::vec3 local[4];  // the quad in the shading frame
    glm::mat3 m_inv;     // the lobe's
    glm::vec3 v_local;
};

struct scene {
    std::vector<config> items;
    std::vector<glm::vec2> u;
    glm::vec3 quad[4];
    const glm::vec3 F0{0.04f}, albedo{0.5f}, radiance{4.0f};

    scene() {
        ltc::ground_truth::splitmix64 g(2021);
        const float a = 1.0471976f;  // 60 degrees about x
        const glm::vec3 centre(0, 0, 1.2f), normal(0, std::sin(a), -std::cos(a)), ax(1, 0, 0);
        const glm::vec3 ay = glm::cross(normal, ax);
        quad[0] = centre - 0.6f * ax - 0.6f * ay;
        quad[1] = centre + 0.6f * ax - 0.6f * ay;
        quad[2] = centre + 0.6f * ax + 0.6f * ay;
        quad[3] = centre - 0.6f * ax + 0.6f * ay;
        const glm::vec3 eye(0, -4, 2);
        for (std::size_t i = 0; i < kItems; ++i) {
            config c;
            c.P = glm::vec3(-2 + 4 * float(i % 32) / 31, -2 + 4 * float(i / 32) / 31, 0);
            const float t = 0.5f * float(g.uniform()), phi = 6.2831853f * float(g.uniform());
            c.N = glm::normalize(glm::vec3(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)));
            c.V = glm::normalize(eye - c.P);
            c.roughness = 0.05f + 0.95f * float(g.uniform());
            const ltc::shading_frame<float> f = ltc::make_shading_frame(c.N, c.V);
            for (int k = 0; k < 4; ++k) c.local[k] = f.to_local(quad[k] - c.P);
            c.m_inv = ltc::ggx::fetch<float>(f.cos_theta_v, c.roughness).m_inv;
            c.v_local = glm::vec3(std::sqrt(1 - f.cos_theta_v * f.cos_theta_v), 0, f.cos_theta_v);
            items.push_back(c);
        }
        for (std::size_t k = 0; k < kSamplesPerItem; ++k) u.push_back(glm::vec2(float(g.uniform()), float(g.uniform())));
    }
};

const scene& the_scene() {
    static const scene s;
    return s;
}

template <typename T>
std::vector<glm::vec<3, T>> local_quad(const config& c) {
    return {glm::vec<3, T>(c.local[0]), glm::vec<3, T>(c.local[1]), glm::vec<3, T>(c.local[2]), glm::vec<3, T>(c.local[3])};
}

// Samples kSamplesPerItem directions from each configuration's sampler.
template <typename T, typename Sampler>
void sample_all(benchmark::State& state, const std::vector<Sampler>& samplers) {
    const scene& s = the_scene();
    int evaluations = 0;
    std::size_t samples = 0;
    for (auto _ : state)
        for (const auto& sm : samplers)
            for (const glm::vec2& u : s.u) {
                benchmark::DoNotOptimize(sm.sample(glm::vec<2, T>(u), evaluations));
                ++samples;
            }
    state.SetItemsProcessed(static_cast<std::int64_t>(samples));
    state.counters["evals"] = double(evaluations) / double(samples);
}

template <typename T>
void projected(benchmark::State& state) {
    std::vector<ltc::projected_polygon_sampler<T>> samplers;
    for (const config& c : the_scene().items) samplers.emplace_back(local_quad<T>(c).data(), 4);
    sample_all<T>(state, samplers);
}

template <typename T>
void ltc_polygon(benchmark::State& state) {
    std::vector<ltc::ltc_polygon_sampler<T>> samplers;
    for (const config& c : the_scene().items)
        samplers.emplace_back(ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(glm::mat<3, 3, T>(c.m_inv)),
                              local_quad<T>(c).data(), 4);
    sample_all<T>(state, samplers);
}

template <typename T>
void projected_setup(benchmark::State& state) {
    const scene& s = the_scene();
    std::vector<std::vector<glm::vec<3, T>>> quads;
    for (const config& c : s.items) quads.push_back(local_quad<T>(c));
    for (auto _ : state)
        for (const auto& q : quads) benchmark::DoNotOptimize(ltc::projected_polygon_sampler<T>(q.data(), 4));
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
}

void area(benchmark::State& state) {
    const scene& s = the_scene();
    const ltc::polygon_area_sampler<float> light(s.quad, 4);
    for (auto _ : state)
        for (const config& c : s.items)
            for (const glm::vec2& u : s.u) {
                const glm::vec3 x = light.sample(u);
                benchmark::DoNotOptimize(light.solid_angle_pdf(c.P, x));
            }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems * kSamplesPerItem));
}

void ggx_brdf(benchmark::State& state) {
    const scene& s = the_scene();
    for (auto _ : state)
        for (const config& c : s.items)
            for (const glm::vec2& u : s.u) {
                const float alpha = c.roughness * c.roughness;
                const glm::vec3 l = ltc::brdf::ggx<float>::sample(c.v_local, u, alpha);
                benchmark::DoNotOptimize(ltc::brdf::ggx<float>::pdf(c.v_local, l, alpha));
            }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems * kSamplesPerItem));
}

void shade(benchmark::State& state) {
    const scene& s = the_scene();
    for (auto _ : state)
        for (const config& c : s.items)
            benchmark::DoNotOptimize(ltc::shade_polygon_light_one_lobe(c.P, c.N, c.V, c.roughness, s.F0, s.albedo,
                                                                       s.radiance, s.quad, 4, ltc::sidedness::one_sided));
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
}

void shade_shadowed(benchmark::State& state, ltc::shadow_sampler sampler) {
    const scene& s = the_scene();
    ltc::shadow_options<float> options;
    options.samples = static_cast<std::size_t>(state.range(0));
    options.sampler = sampler;
    std::size_t rays = 0;
    const auto visible = [](const glm::vec3&, const glm::vec3&, float) { return true; };
    for (auto _ : state)
        for (const config& c : s.items) {
            const auto r = ltc::shade_polygon_light_shadowed(c.P, c.N, c.V, c.roughness, s.F0, s.albedo, s.radiance,
                                                             s.quad, 4, ltc::sidedness::one_sided, visible, options);
            rays += r.rays;
            benchmark::DoNotOptimize(r);
        }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
    state.counters["rays"] = double(rays) / double(state.iterations() * kItems);
}

}  // namespace

BENCHMARK_TEMPLATE(projected, float);
BENCHMARK_TEMPLATE(projected, double);
BENCHMARK_TEMPLATE(ltc_polygon, float);
BENCHMARK_TEMPLATE(ltc_polygon, double);
BENCHMARK_TEMPLATE(projected_setup, float);
BENCHMARK_TEMPLATE(projected_setup, double);
BENCHMARK(area);
BENCHMARK(ggx_brdf);
BENCHMARK(shade);
BENCHMARK_CAPTURE(shade_shadowed, ltc_polygon, ltc::shadow_sampler::ltc_polygon)->Arg(1)->Arg(4)->Arg(16);
BENCHMARK_CAPTURE(shade_shadowed, light_area, ltc::shadow_sampler::light_area)->Arg(1)->Arg(4)->Arg(16);

LTC_BENCHMARK_MAIN();
