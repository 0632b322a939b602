// GGX shading of one quad light over 4096 shading points (a renderer's pass over its pixels):
// the reference shader's shading (reference_shading.hpp: frame, two bilinear fetches, two
// 16-case-clipped integrals), ltc::shade<Model>(surface, light) point by point for each GGX model
// and ltc::ggx::anisotropic (BM_shade), ltc::shade_polygon_light_one_lobe point by point (BM_library_scalar),
// and ltc::batch::shade_polygon_light_one_lobe (one point per SIMD lane); and one point shaded by
// 4096 quad lights (ltc::batch::shade_quad_lights_one_lobe); and ltc::shade_polygon_light_two_lobe
// point by point and ltc::batch::shade_polygon_light_two_lobe (the opt-in two-lobe table), and
// ltc::shade_polygon_light_cosine_lobe point by point and in batches (the table of an LTC and the
// cosine: ltc::shade_polygon_light, ltc::batch::shade_polygon_light and shade_quad_lights, the
// defaults, are these functions), with the quad-light batches of both: their costs against the
// one-lobe ones, no error counters since they are other approximations. Items/s plus, as
// counters, the maximum absolute and relative error of specular + diffuse (red) against
// ltc::shade_polygon_light_one_lobe in double with the
// exact edge policy: the precision each float path loses, not the LTC approximation's own error.
//
// The points: a 64 x 64 grid on the floor z = 0 of a room, normals tilted up to 30 degrees from
// +z, seen from a camera at (0, -4, 2), roughness and colours varying over the grid; the light:
// a 1.5 x 0.8 quad at height 1.2, tilted by 60 degrees, so that it crosses the horizon of part of
// the points. Built in the same variants as bench_batch (benchmarks/CMakeLists.txt).
#include "bench_main.hpp"
#include "reference_shading.hpp"

#include <ltc/reference/splitmix64.hpp>
#include <ltc/shading/batch_shading.hpp>
#include <ltc/shading/batch_cosine_lobe.hpp>
#include <ltc/shading/batch_two_lobe.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/two_lobe_polygon_light.hpp>
#include <ltc/shading/cosine_lobe_polygon_light.hpp>
#include <ltc/shading/ggx_anisotropic_model.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/shade.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace {

constexpr std::size_t kItems = 4096;

struct scene {
    std::vector<float> a[16];  // px py pz nx ny nz vx vy vz roughness f0 rgb albedo rgb
    glm::vec3 light[4];
    glm::vec3 radiance{4.0f, 3.5f, 3.0f};

    scene() {
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
        light[0] = centre - ex - ey, light[1] = centre + ex - ey, light[2] = centre + ex + ey, light[3] = centre - ex + ey;
    }
    glm::vec3 vec(int c, std::size_t i) const { return glm::vec3(a[c][i], a[c + 1][i], a[c + 2][i]); }
    ltc::batch::shading_points<float> points() const {
        const float* c[16];
        for (int k = 0; k < 16; ++k) c[k] = a[k].data();
        return ltc::batch::shading_points<float>::from_columns(c);
    }
};

const scene& the_scene() {
    static const scene s;
    return s;
}

// specular + diffuse, red, in double with the exact policy.
const std::vector<double>& exact() {
    static const std::vector<double> e = [] {
        const scene& s = the_scene();
        glm::dvec3 L[4];
        for (int k = 0; k < 4; ++k) L[k] = glm::dvec3(s.light[k]);
        std::vector<double> v;
        for (std::size_t i = 0; i < kItems; ++i) {
            const auto r = ltc::shade_polygon_light_one_lobe<ltc::edge_policy::exact>(
                glm::dvec3(s.vec(0, i)), glm::dvec3(s.vec(3, i)), glm::dvec3(s.vec(6, i)), double(s.a[9][i]),
                glm::dvec3(s.vec(10, i)), glm::dvec3(s.vec(13, i)), glm::dvec3(s.radiance), L, 4,
                ltc::sidedness::two_sided);
            v.push_back(r.specular.x + r.diffuse.x);
        }
        return v;
    }();
    return e;
}

void report_errors(benchmark::State& state, const std::vector<float>& red) {
    double max_abs = 0, max_rel = 0;
    for (std::size_t i = 0; i < kItems; ++i) {
        const double e = exact()[i], err = std::abs(double(red[i]) - e);
        max_abs = std::max(max_abs, err);
        if (e > 1e-3) max_rel = std::max(max_rel, err / e);
    }
    state.counters["max_abs_err"] = max_abs;
    state.counters["max_rel_err(>1e-3)"] = max_rel;
}

void BM_reference_shading(benchmark::State& state) {
    const scene& s = the_scene();
    std::vector<float> red(kItems);
    for (auto _ : state) {
        for (std::size_t i = 0; i < kItems; ++i) {
            const auto r = reference_shading::shade(s.vec(0, i), glm::normalize(s.vec(3, i)), glm::normalize(s.vec(6, i)),
                                                    s.a[9][i], s.vec(10, i), s.vec(13, i), s.radiance, s.light, true);
            red[i] = r.specular.x + r.diffuse.x;
        }
        benchmark::DoNotOptimize(red.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
    report_errors(state, red);
}

template <typename Policy>
void BM_library_scalar(benchmark::State& state) {
    const scene& s = the_scene();
    std::vector<float> red(kItems);
    for (auto _ : state) {
        for (std::size_t i = 0; i < kItems; ++i) {
            const auto r = ltc::shade_polygon_light_one_lobe<Policy>(s.vec(0, i), s.vec(3, i), s.vec(6, i), s.a[9][i],
                                                                     s.vec(10, i), s.vec(13, i), s.radiance, s.light, 4,
                                                                     ltc::sidedness::two_sided);
            red[i] = r.specular.x + r.diffuse.x;
        }
        benchmark::DoNotOptimize(red.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
    report_errors(state, red);
}

// The other tables point by point: Cosine false, shade_polygon_light_two_lobe (the opt-in table,
// two LTC integrals); true, shade_polygon_light_cosine_lobe (the default shade_polygon_light: one
// LTC integral and the form factor, as BM_library_scalar, and a second table fetch). Throughput
// only.
template <typename Policy, bool Cosine>
void BM_library_scalar_opt_in(benchmark::State& state) {
    const scene& s = the_scene();
    std::vector<float> red(kItems);
    for (auto _ : state) {
        for (std::size_t i = 0; i < kItems; ++i) {
            const auto shade = [&](const auto&... a) {
                if constexpr (Cosine)
                    return ltc::shade_polygon_light_cosine_lobe<Policy>(a...);
                else
                    return ltc::shade_polygon_light_two_lobe<Policy>(a...);
            };
            const auto r = shade(s.vec(0, i), s.vec(3, i), s.vec(6, i), s.a[9][i], s.vec(10, i), s.vec(13, i), s.radiance,
                                 s.light, std::size_t(4), ltc::sidedness::two_sided);
            red[i] = r.specular.x + r.diffuse.x;
        }
        benchmark::DoNotOptimize(red.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
}
template <typename Policy>
void BM_library_scalar_two_lobe(benchmark::State& state) { BM_library_scalar_opt_in<Policy, false>(state); }
template <typename Policy>
void BM_library_scalar_cosine_lobe(benchmark::State& state) { BM_library_scalar_opt_in<Policy, true>(state); }

// ltc::shade<Model>(surface, light) point by point, as a renderer calls it: the surface built per
// point, the light once (the deprecated names above build both per call and forward to it).
template <typename Model>
void BM_shade(benchmark::State& state) {
    const scene& s = the_scene();
    const auto light = ltc::polygon_light<float>::two_sided(s.light, 4, s.radiance);
    const glm::vec3 tangent(1.0f, 0.25f, 0.0f);
    std::vector<float> red(kItems);
    for (auto _ : state) {
        for (std::size_t i = 0; i < kItems; ++i) {
            // Every model gets the anisotropic fields (a brushing direction, another point's
            // roughness across it), so that all build the same surface.
            const ltc::surface<float> p{s.vec(0, i),  s.vec(3, i),  s.vec(6, i), s.a[9][i], s.vec(10, i),
                                        s.vec(13, i), tangent, s.a[9][(i * 7) % kItems]};
            const auto r = ltc::shade<Model>(p, light);
            red[i] = r.specular.x + r.diffuse.x;
        }
        benchmark::DoNotOptimize(red.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
    if (std::is_same_v<Model, ltc::ggx::one_lobe>) report_errors(state, red);
}

struct outputs {
    std::vector<float> c[6];
    outputs() {
        for (auto& v : c) v.resize(kItems);
    }
    ltc::batch::shading_results<float> results() {
        ltc::batch::shading_results<float> r;
        for (int k = 0; k < 3; ++k) r.specular[k] = c[k].data(), r.diffuse[k] = c[3 + k].data();
        return r;
    }
    std::vector<float> red() const {
        std::vector<float> v(kItems);
        for (std::size_t i = 0; i < kItems; ++i) v[i] = c[0][i] + c[3][i];
        return v;
    }
};

template <ltc::batch::isa Isa>
void BM_batch_shading(benchmark::State& state) {
    if (!ltc::batch::available(Isa)) {
        state.SkipWithError("instruction set not available on this CPU");
        return;
    }
    const scene& s = the_scene();
    const auto points = s.points();
    outputs out;
    const auto results = out.results();
    for (auto _ : state) {
        ltc::batch::shade_polygon_light_one_lobe(points, s.radiance, s.light, 4, ltc::sidedness::two_sided, results, kItems,
                                                 Isa);
        benchmark::DoNotOptimize(out.c[0].data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
    report_errors(state, out.red());
}

// The other tables' batches, throughput only, as BM_library_scalar_opt_in: Cosine false, the two-lobe
// batch (ltc/shading/batch_two_lobe.hpp); true, the batch of an LTC and the cosine
// (ltc/shading/batch_cosine_lobe.hpp), also with each instruction set pinned, against the
// one-lobe BM_batch_shading<isa> rows (the goal set for the opt-in tables: at most 1.2x the
// one-lobe cost).
template <bool Cosine, ltc::batch::isa Which = ltc::batch::isa::automatic>
void BM_batch_shading_opt_in(benchmark::State& state) {
    const scene& s = the_scene();
    const auto points = s.points();
    outputs out;
    const auto results = out.results();
    for (auto _ : state) {
        if (Cosine)
            ltc::batch::shade_polygon_light_cosine_lobe(points, s.radiance, s.light, 4, ltc::sidedness::two_sided, results,
                                                        kItems, Which);
        else
            ltc::batch::shade_polygon_light_two_lobe(points, s.radiance, s.light, 4, ltc::sidedness::two_sided, results,
                                                     kItems, Which);
        benchmark::DoNotOptimize(out.c[0].data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
}

// One point (the grid's centre) and 4096 copies of the light moved about: throughput only.
// Lobes = 2: ltc::batch::shade_quad_lights_two_lobe; 3: ltc::batch::shade_quad_lights_cosine_lobe.
template <int Lobes>
void BM_batch_quad_lights(benchmark::State& state) {
    const scene& s = the_scene();
    const std::size_t i = 32 * 64 + 32;
    std::vector<float> v[15];
    ltc::ground_truth::splitmix64 g(7);
    for (std::size_t j = 0; j < kItems; ++j) {
        const glm::vec3 shift(float(g.uniform()) - 0.5f, float(g.uniform()) - 0.5f, 0.5f * float(g.uniform()));
        for (int k = 0; k < 4; ++k) {
            const glm::vec3 p = s.light[k] + shift;
            v[k].push_back(p.x), v[4 + k].push_back(p.y), v[8 + k].push_back(p.z);
        }
        for (int c = 0; c < 3; ++c) v[12 + c].push_back(s.radiance[c]);
    }
    ltc::batch::quad_lights<float> lights;
    for (int k = 0; k < 4; ++k) lights.x[k] = v[k].data(), lights.y[k] = v[4 + k].data(), lights.z[k] = v[8 + k].data();
    for (int c = 0; c < 3; ++c) lights.radiance[c] = v[12 + c].data();
    outputs out;
    const auto results = out.results();
    for (auto _ : state) {
        if (Lobes == 3)
            ltc::batch::shade_quad_lights_cosine_lobe(s.vec(0, i), s.vec(3, i), s.vec(6, i), s.a[9][i], s.vec(10, i),
                                                      s.vec(13, i), lights, ltc::sidedness::two_sided, results, kItems);
        else if (Lobes == 1)
            ltc::batch::shade_quad_lights_one_lobe(s.vec(0, i), s.vec(3, i), s.vec(6, i), s.a[9][i], s.vec(10, i),
                                                   s.vec(13, i), lights, ltc::sidedness::two_sided, results, kItems);
        else
            ltc::batch::shade_quad_lights_two_lobe(s.vec(0, i), s.vec(3, i), s.vec(6, i), s.a[9][i], s.vec(10, i),
                                                   s.vec(13, i), lights, ltc::sidedness::two_sided, results, kItems);
        benchmark::DoNotOptimize(out.c[0].data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
}

}  // namespace

using ltc::batch::isa;
BENCHMARK(BM_reference_shading);
BENCHMARK_TEMPLATE(BM_library_scalar, ltc::edge_policy::exact);
BENCHMARK_TEMPLATE(BM_library_scalar, ltc::edge_policy::minimax_rational);
BENCHMARK_TEMPLATE(BM_library_scalar_two_lobe, ltc::edge_policy::exact);
BENCHMARK_TEMPLATE(BM_library_scalar_two_lobe, ltc::edge_policy::minimax_rational);
BENCHMARK_TEMPLATE(BM_library_scalar_cosine_lobe, ltc::edge_policy::exact);
BENCHMARK_TEMPLATE(BM_library_scalar_cosine_lobe, ltc::edge_policy::minimax_rational);
BENCHMARK_TEMPLATE(BM_shade, ltc::ggx::one_lobe);
BENCHMARK_TEMPLATE(BM_shade, ltc::ggx::ltc_and_cosine);
BENCHMARK_TEMPLATE(BM_shade, ltc::ggx::two_lobes);
BENCHMARK_TEMPLATE(BM_shade, ltc::ggx::anisotropic);
BENCHMARK_TEMPLATE(BM_batch_shading, isa::automatic);
BENCHMARK_TEMPLATE(BM_batch_shading, isa::baseline);
BENCHMARK_TEMPLATE(BM_batch_shading, isa::avx2);
BENCHMARK_TEMPLATE(BM_batch_shading, isa::avx512);
BENCHMARK_TEMPLATE(BM_batch_shading_opt_in, false)->Name("BM_batch_shading_two_lobe");
BENCHMARK_TEMPLATE(BM_batch_shading_opt_in, true)->Name("BM_batch_shading_cosine_lobe");
BENCHMARK_TEMPLATE(BM_batch_shading_opt_in, true, isa::baseline)->Name("BM_batch_shading_cosine_lobe<isa::baseline>");
BENCHMARK_TEMPLATE(BM_batch_shading_opt_in, true, isa::avx2)->Name("BM_batch_shading_cosine_lobe<isa::avx2>");
BENCHMARK_TEMPLATE(BM_batch_shading_opt_in, true, isa::avx512)->Name("BM_batch_shading_cosine_lobe<isa::avx512>");
BENCHMARK_TEMPLATE(BM_batch_quad_lights, 1);
BENCHMARK_TEMPLATE(BM_batch_quad_lights, 2);
BENCHMARK_TEMPLATE(BM_batch_quad_lights, 3);

LTC_BENCHMARK_MAIN();
