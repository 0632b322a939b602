// Line, disk and sphere lights (ltc/shading/lights/): the cost of one float shading call of each shape
// against the quad light's, over the same 4096 shading points (a 64 x 64 grid on the floor z = 0
// of a room, normals tilted up to 30 degrees, seen from a camera at (0, -4, 2), roughness 0.05-1
// over the grid). The lights, all centred at (0, 0, 1.2) and tilted by 60 degrees about x, so
// that they cross the horizon of part of the points:
//   quad     ltc::shade_polygon_light_one_lobe, a 1.2 x 1.2 square, one-sided (the reference for speed:
//            the shapes' table);
//   disk     ltc::shade_disk_light, radius 0.6, one-sided; disk_2017 the same call with
//            integrate_disk_2017 for both terms; disk_polygon_16 integrate_disk_polygon, 16 edges;
//   sphere   ltc::shade_sphere_light, radius 0.6;
//   tube     ltc::shade_line_light, axis 1.2 long, radius 0.05; tube_ribbon ltc::shade_tube_light,
//            the same tube as its ribbon quad (the exact silhouette, a two-sided polygon).
// time_per_item (CPU time) is the cost of one shading call (specular + diffuse); compare the
// shapes' to the quad's within one run:
//   ./build/benchmarks/bench_shapes --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//       --benchmark_enable_random_interleaving=true
#include "bench_main.hpp"

#include <ltc/core/ellipse_integral.hpp>
#include <ltc/reference/splitmix64.hpp>
#include <ltc/shading/disk_light.hpp>
#include <ltc/shading/line_light.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/sphere_light.hpp>
#include <ltc/shading/tube_light.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

constexpr std::size_t kItems = 4096;

struct point {
    glm::vec3 P, N, V;
    float roughness;
};

struct scene {
    std::vector<point> points;
    glm::vec3 centre{0, 0, 1.2f}, normal, u, v;  // the lights' plane: normal, and two axes in it
    glm::vec3 quad[4];
    const glm::vec3 F0{0.04f}, albedo{0.8f, 0.6f, 0.4f}, radiance{4.0f, 3.5f, 3.0f};

    scene() {
        ltc::ground_truth::splitmix64 g(2017);
        const glm::vec3 eye(0, -4, 2);
        for (std::size_t i = 0; i < kItems; ++i) {
            point p;
            p.P = glm::vec3(-2 + 4 * float(i % 64) / 63, -2 + 4 * float(i / 64) / 63, 0);
            const float t = 0.5f * float(g.uniform()), phi = 6.2831853f * float(g.uniform());
            p.N = glm::normalize(glm::vec3(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)));
            p.V = glm::normalize(eye - p.P);
            p.roughness = 0.05f + 0.95f * float(g.uniform());
            points.push_back(p);
        }
        const float a = 1.0471976f;  // 60 degrees about x
        normal = glm::vec3(0, std::sin(a), -std::cos(a));
        u = glm::vec3(1, 0, 0);
        v = glm::cross(normal, u);
        for (int k = 0; k < 4; ++k) {
            const float su = (k == 1 || k == 2) ? 0.6f : -0.6f, sv = k >= 2 ? 0.6f : -0.6f;
            quad[k] = centre + su * u + sv * v;
        }
    }
};

const scene& the_scene() {
    static const scene s;
    return s;
}

template <typename Shade>
void run(benchmark::State& state, Shade shade) {
    const scene& s = the_scene();
    std::vector<glm::vec3> out(kItems);
    for (auto _ : state) {
        for (std::size_t i = 0; i < kItems; ++i) {
            const ltc::polygon_light_result<float> r = shade(s, s.points[i]);
            out[i] = r.specular + r.diffuse;
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kItems));
    state.counters["time_per_item"] =
        benchmark::Counter(double(kItems), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// A disk light through the given integral of an LTC over a disk (both terms), as shade_disk_light.
template <typename Integral>
ltc::polygon_light_result<float> shade_disk_with(const scene& s, const point& p, Integral integral) {
    ltc::polygon_light_result<float> r;
    const ltc::shading_frame<float> frame = ltc::make_shading_frame(p.N, p.V);
    if (!frame.valid) return r;
    const ltc::ltc_coefficients<float> c = ltc::ggx::fetch<float>(frame.cos_theta_v, p.roughness);
    const glm::vec3 centre = frame.to_local(s.centre - p.P), normal = frame.to_local(s.normal);
    const auto spec = ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(c.m_inv);
    const auto cosine = ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(glm::mat3(1.0f));
    r.specular = s.radiance * (s.F0 * c.magnitude + (glm::vec3(1) - s.F0) * c.fresnel) * integral(spec, centre, normal);
    r.diffuse = s.albedo * s.radiance * integral(cosine, centre, normal);
    return r;
}

void BM_quad(benchmark::State& state) {
    run(state, [](const scene& s, const point& p) {
        return ltc::shade_polygon_light_one_lobe(p.P, p.N, p.V, p.roughness, s.F0, s.albedo, s.radiance, s.quad, 4,
                                                 ltc::sidedness::one_sided);
    });
}

void BM_disk(benchmark::State& state) {
    run(state, [](const scene& s, const point& p) {
        return ltc::shade_disk_light(p.P, p.N, p.V, p.roughness, s.F0, s.albedo, s.radiance, s.centre, s.normal, 0.6f,
                                     ltc::sidedness::one_sided);
    });
}

void BM_disk_2017(benchmark::State& state) {
    run(state, [](const scene& s, const point& p) {
        return shade_disk_with(s, p, [](const auto& d, const glm::vec3& c, const glm::vec3& n) {
            return ltc::integrate_disk_2017(d, c, n, 0.6f, ltc::sidedness::one_sided);
        });
    });
}

void BM_disk_polygon_16(benchmark::State& state) {
    run(state, [](const scene& s, const point& p) {
        return shade_disk_with(s, p, [](const auto& d, const glm::vec3& c, const glm::vec3& n) {
            return ltc::integrate_disk_polygon(d, c, n, 0.6f, 16, ltc::sidedness::one_sided);
        });
    });
}

void BM_sphere(benchmark::State& state) {
    run(state, [](const scene& s, const point& p) {
        return ltc::shade_sphere_light(p.P, p.N, p.V, p.roughness, s.F0, s.albedo, s.radiance, s.centre, 0.6f);
    });
}

void BM_tube(benchmark::State& state) {
    run(state, [](const scene& s, const point& p) {
        return ltc::shade_line_light(p.P, p.N, p.V, p.roughness, s.F0, s.albedo, s.radiance, s.centre - 0.6f * s.u,
                                     s.centre + 0.6f * s.u, 0.05f);
    });
}

void BM_tube_ribbon(benchmark::State& state) {
    run(state, [](const scene& s, const point& p) {
        return ltc::shade_tube_light(p.P, p.N, p.V, p.roughness, s.F0, s.albedo, s.radiance, s.centre - 0.6f * s.u,
                                     s.centre + 0.6f * s.u, 0.05f);
    });
}

}  // namespace

BENCHMARK(BM_quad);
BENCHMARK(BM_disk);
BENCHMARK(BM_disk_2017);
BENCHMARK(BM_disk_polygon_16);
BENCHMARK(BM_sphere);
BENCHMARK(BM_tube);
BENCHMARK(BM_tube_ribbon);

LTC_BENCHMARK_MAIN();
