// libFuzzer harness of the shading, the shadows and the batches: for any finite polygon (0..15
// vertices), P, N, V and roughness, GGX polygon-light shading is finite, with one or two lobes or
// an LTC and the cosine (the default shading is bitwise the latter), point by point with each
// horizon-clipping strategy and in batches (17 points, and a quad light 17 times over one point,
// with each instruction set); with shadows (the ratio estimator and its two sums per term, any
// sample plan, any analytic part, a boolean or first-hit callback, by shade_polygon_light_shadowed
// and by ltc::shade_shadowed<Model> with a light one-sided by emission normal) every term,
// estimate and the blockers' sums are finite and in range, and shade_shadowed's analytic part is
// ltc::shade<Model>'s bit for bit; and the batch API of the integrals (fuzz_batch.hpp:
// batches of 1..19 quads or n-gons) agrees with the scalar path.
// Per input one of four parts (the point's shading and shadows, batch shading, the batch
// integrals, anisotropic GGX: check_anisotropic), and within it one horizon-clipping strategy, or
// one instruction set, table (one lobe, two, or the LTC and the cosine) and the point's or the
// quad light's batch, or fuzz_batch.hpp's one shape, policy, instruction set and sidedness
// (fuzzed bytes): over a run they cover every combination, at a fraction of the cost per input of
// running them all. Input: fuzz_common.hpp's read_scene and read_shading_point, the part's byte,
// then check_batch's input, or a byte of choices (and the shadow options, then the emission
// normal's side; or the anisotropic part's tangent and second roughness). Build and run:
// tests/fuzz/run.sh (README.md there).
#include "fuzz_batch.hpp"
#include "fuzz_common.hpp"

#include <ltc/core/screen_order.hpp>
#include <ltc/shading/batch.hpp>
#include <ltc/shading/batch_cosine_lobe.hpp>
#include <ltc/shading/batch_shading.hpp>
#include <ltc/shading/batch_two_lobe.hpp>
#include <ltc/shading/cosine_lobe_polygon_light.hpp>
#include <ltc/shading/ggx_anisotropic_model.hpp>
#include <ltc/shading/lights/light_error.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/shade.hpp>
#include <ltc/shading/shade_shadowed.hpp>
#include <ltc/shading/shadowed_polygon_light.hpp>
#include <ltc/shading/two_lobe_polygon_light.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <vector>

namespace {

using namespace ltc_fuzz;

// World-space GGX shading with one horizon-clipping strategy: one lobe, two lobes, an LTC and the
// cosine, and the default (which is the LTC and the cosine, ltc/shading/polygon_light.hpp).
template <typename T>
void check_point_shading(const std::vector<glm::vec<3, T>>& v, const shading_point<T>& s, ltc::horizon_clipping clip) {
    using vec3 = glm::vec<3, T>;
    const vec3 *pv = v.data(), P = s.P, N = s.N, V = s.V;
    const std::size_t n = v.size();
    const T roughness = s.roughness;
    const auto r = ltc::shade_polygon_light_one_lobe(P, N, V, roughness, vec3(T(0.04)), vec3(T(0.5)), vec3(T(1)), pv, n,
                                                     ltc::sidedness::two_sided, clip);
    require_finite(r.specular, "GGX specular");
    require_finite(r.diffuse, "GGX diffuse");
    const auto r2 = ltc::shade_polygon_light_two_lobe(P, N, V, roughness, vec3(T(0.04)), vec3(T(0.5)), vec3(T(1)), pv,
                                                      n, ltc::sidedness::two_sided, clip);
    require_finite(r2.specular, "two-lobe GGX specular");
    require_finite(r2.diffuse, "two-lobe GGX diffuse");
    const auto r3 = ltc::shade_polygon_light_cosine_lobe(P, N, V, roughness, vec3(T(0.04)), vec3(T(0.5)), vec3(T(1)),
                                                         pv, n, ltc::sidedness::two_sided, clip);
    require_finite(r3.specular, "LTC and cosine GGX specular");
    require_finite(r3.diffuse, "LTC and cosine GGX diffuse");
    const auto r0 = ltc::shade_polygon_light(P, N, V, roughness, vec3(T(0.04)), vec3(T(0.5)), vec3(T(1)), pv, n,
                                             ltc::sidedness::two_sided, clip);
    if (!(r0.specular == r3.specular && r0.diffuse == r3.diffuse)) {
        std::fprintf(stderr, "the default shading differs from shade_polygon_light_cosine_lobe\n");
        std::abort();
    }
}

// Batch shading's 17 results (full vectors and a tail at every width), checked finite.
template <typename T>
struct batch_results {
    static constexpr std::size_t count = 17;
    std::vector<T> r[6];
    ltc::batch::shading_results<T> out;
    batch_results() {
        for (auto& x : r) x.assign(count, T(0));
        for (int c = 0; c < 3; ++c) out.specular[c] = r[c].data(), out.diffuse[c] = r[3 + c].data();
    }
    void require_finite(const char* what) const {
        for (const auto& x : r)
            for (const T y : x) ltc_fuzz::require_finite(y, what);
    }
};

// Batch shading (ltc/shading/batch_shading.hpp and the two-lobe and cosine-lobe ones), one lobe,
// two lobes, or an LTC and the cosine (`lobes` 1, 2, 3), with one instruction set: a quad light
// (the polygon's first four vertices) 17 times over one point, through the quad-light batch of
// the lobes' table.
template <typename T>
void check_quad_light_batch(const std::vector<glm::vec<3, T>>& v, const shading_point<T>& s, ltc::batch::isa isa,
                            int lobes) {
    using vec3 = glm::vec<3, T>;
    const vec3 *pv = v.data(), P = s.P, N = s.N, V = s.V;
    const T roughness = s.roughness;
    batch_results<T> res;
    constexpr std::size_t count = batch_results<T>::count;
    auto& out = res.out;
    std::vector<T> q[15];
    for (std::size_t j = 0; j < count; ++j) {
        for (int k = 0; k < 4; ++k) q[k].push_back(pv[k].x), q[4 + k].push_back(pv[k].y), q[8 + k].push_back(pv[k].z);
        for (int c = 0; c < 3; ++c) q[12 + c].push_back(T(1));
    }
    ltc::batch::quad_lights<T> lights;
    for (int k = 0; k < 4; ++k) lights.x[k] = q[k].data(), lights.y[k] = q[4 + k].data(), lights.z[k] = q[8 + k].data();
    for (int c = 0; c < 3; ++c) lights.radiance[c] = q[12 + c].data();
    const vec3 F0(T(0.04)), albedo(T(0.5));
    if (lobes == 1)
        ltc::batch::shade_quad_lights_one_lobe(P, N, V, roughness, F0, albedo, lights, ltc::sidedness::two_sided, out,
                                               count, isa);
    else if (lobes == 2)
        ltc::batch::shade_quad_lights_two_lobe(P, N, V, roughness, F0, albedo, lights, ltc::sidedness::two_sided, out,
                                               count, isa);
    else
        ltc::batch::shade_quad_lights_cosine_lobe(P, N, V, roughness, F0, albedo, lights, ltc::sidedness::two_sided,
                                                  out, count, isa);
    res.require_finite("quad-light batch GGX shading");
}

// The same, the fuzzed point 17 times over (roughness from the fuzzed one to 1) and the polygon.
template <typename T>
void check_point_batch(const std::vector<glm::vec<3, T>>& v, const shading_point<T>& s, ltc::batch::isa isa,
                       int lobes) {
    using vec3 = glm::vec<3, T>;
    const vec3 *pv = v.data(), P = s.P, N = s.N, V = s.V;
    const std::size_t n = v.size();
    const T roughness = s.roughness;
    batch_results<T> res;
    constexpr std::size_t count = batch_results<T>::count;
    std::vector<T> columns[16];
    for (int c = 0; c < 16; ++c) columns[c].assign(count, T(0));
    for (std::size_t i = 0; i < count; ++i) {
        const T values[10] = {P.x, P.y, P.z, N.x, N.y, N.z, V.x, V.y, V.z,
                              roughness + (T(1) - roughness) * T(i) / T(count - 1)};
        for (int c = 0; c < 10; ++c) columns[c][i] = values[c];
        for (int c = 10; c < 13; ++c) columns[c][i] = T(0.04);
        for (int c = 13; c < 16; ++c) columns[c][i] = T(0.5);
    }
    ltc::batch::shading_points<T> points;
    const T** fields[16] = {&points.px, &points.py, &points.pz, &points.nx, &points.ny, &points.nz,
                            &points.vx, &points.vy, &points.vz, &points.roughness, &points.f0[0], &points.f0[1],
                            &points.f0[2], &points.albedo[0], &points.albedo[1], &points.albedo[2]};
    for (int c = 0; c < 16; ++c) *fields[c] = columns[c].data();
    if (lobes == 3)
        ltc::batch::shade_polygon_light_cosine_lobe(points, vec3(T(1)), pv, n, ltc::sidedness::two_sided, res.out,
                                                    count, isa);
    else if (lobes == 1)
        ltc::batch::shade_polygon_light_one_lobe(points, vec3(T(1)), pv, n, ltc::sidedness::two_sided, res.out, count,
                                                 isa);
    else
        ltc::batch::shade_polygon_light_two_lobe(points, vec3(T(1)), pv, n, ltc::sidedness::two_sided, res.out, count,
                                                 isa);
    res.require_finite("batch GGX shading");
}

// The outputs of the shadowed shading: every term, estimate and the blockers' sums finite and in
// range (blockers only with a first-hit callback).
template <typename T>
void require_shadowed_in_range(const ltc::shadowed_polygon_light_result<T>& r, bool first_hit) {
    using vec3 = glm::vec<3, T>;
    require_finite(r.blockers.ratio_sum, "blockers' ratio sum");
    require_finite(ltc::penumbra_width(T(1), r.blockers), "penumbra width");
    if (!(r.blockers.ratio_sum >= T(0) && r.blockers.occluded <= T(r.rays) &&
          (first_hit || r.blockers.occluded == T(0)))) {
        std::fprintf(stderr, "blockers out of range: sum %g over %g occluded of %zu queries\n",
                     static_cast<double>(r.blockers.ratio_sum), static_cast<double>(r.blockers.occluded), r.rays);
        std::abort();
    }
    for (const auto* t : {&r.unshadowed, &r.ratio, &r.unbiased}) {
        require_finite(t->specular, "shadowed specular");
        require_finite(t->diffuse, "shadowed diffuse");
    }
    for (const auto* e : {&r.specular_estimates, &r.specular_fresnel_estimates, &r.diffuse_estimates}) {
        require_finite(e->visible, "shadowed estimate");
        require_finite(e->total, "unshadowed estimate");
        require_finite(e->analytic, "analytic estimate");
    }
    // The corrected specular term, of the pixel's own estimates (its filter-free use).
    require_finite(ltc::corrected_specular(vec3(T(0.04)), vec3(T(1)), r.specular_estimates.analytic,
                                           r.specular_fresnel_estimates.analytic, r.specular_estimates,
                                           r.specular_fresnel_estimates),
                   "corrected specular");
}

// ltc::shade_shadowed<Model> with the light one-sided towards its vector area (or away from it,
// `back`; where the light accepts the normal: not zero, finite, off the polygon's plane): in range
// as above, and, for the 3..8 vertices it shades, its analytic part ltc::shade<Model>'s bits.
template <typename Model, typename T>
void check_shade_shadowed(const scene<T>& sc, const shading_point<T>& s, const ltc::shadow_sampling<T>& o, bool back,
                          bool first_hit, T hit_fraction) {
    using vec3 = glm::vec<3, T>;
    const std::size_t n = sc.v.size();
    vec3 normal = n >= 3 ? ltc::detail::vector_area_x2(sc.v.data(), n) : vec3(T(0));
    if (normal == vec3(T(0))) normal = vec3(T(0), T(0), T(1));
    if (back) normal = -normal;
    const ltc::surface<T> surface{s.P, s.N, s.V, s.roughness, vec3(T(0.04)), vec3(T(0.5))};
    std::size_t queries = 0;
    const auto alternate = [&](const vec3&, const vec3&, T) { return (queries++ & 1u) == 0; };
    const auto occluder_at = [&](const vec3&, const vec3&, T distance) {
        return (queries++ & 1u) == 0 ? std::numeric_limits<T>::infinity() : distance * hit_fraction;
    };
    try {
        const auto light = ltc::polygon_light<T>::one_sided(sc.v.data(), n, normal, vec3(T(1)));
        const auto r = first_hit ? ltc::shade_shadowed<Model>(surface, light, ltc::first_hit(occluder_at), o)
                                 : ltc::shade_shadowed<Model>(surface, light, alternate, o);
        require_shadowed_in_range(r, first_hit);
        const ltc::shading_result<T> want = ltc::shade<Model>(surface, light);
        if (n >= 3 && n <= 8 && !(std::memcmp(&r.unshadowed.specular, &want.specular, sizeof(vec3)) == 0 &&
                                  std::memcmp(&r.unshadowed.diffuse, &want.diffuse, sizeof(vec3)) == 0)) {
            std::fprintf(stderr, "shade_shadowed's analytic part differs from ltc::shade's\n");
            std::abort();
        }
    } catch (const ltc::invalid_light&) {
        // a normal the light refuses (its area overflows, or lies in its plane by rounding)
    }
}

// Shadowed shading (the ratio estimator): any sample plan, any analytic part, by the deprecated
// name (the old sidedness rule) and by ltc::shade_shadowed<Model>; the visibility alternates, so
// that both of each ratio's sums see samples.
template <typename T>
void check_shadowed(FuzzedDataProvider& in, const scene<T>& sc, const shading_point<T>& s) {
    using vec3 = glm::vec<3, T>;
    std::size_t queries = 0;
    const auto alternate = [&](const vec3&, const vec3&, T) { return (queries++ & 1u) == 0; };
    ltc::shadow_options<T> o;
    o.samples = in.ConsumeIntegralInRange<std::size_t>(0, 8);
    o.rotation = sc.u;
    if (in.ConsumeBool()) {  // a screen-ordered rotation of any pixel and seed (ltc/core/screen_order.hpp)
        const std::uint32_t x = in.ConsumeIntegral<std::uint32_t>(), y = in.ConsumeIntegral<std::uint32_t>();
        o.rotation = ltc::screen_point<T>(x, y, in.ConsumeIntegral<std::uint64_t>());
        o.stratified_rotation = true;
        if (!(o.rotation.x >= T(0) && o.rotation.x < T(1) && o.rotation.y >= T(0) && o.rotation.y < T(1))) {
            std::fprintf(stderr, "screen rotation outside [0, 1)^2: (%g, %g)\n", static_cast<double>(o.rotation.x),
                         static_cast<double>(o.rotation.y));
            std::abort();
        }
    }
    o.sampler = in.ConsumeBool() ? ltc::shadow_sampler::ltc_polygon : ltc::shadow_sampler::light_area;
    o.diffuse = in.ConsumeBool() ? ltc::diffuse_sampler::cosine : ltc::diffuse_sampler::light_area;
    o.rejection_from = T(2) * in.ConsumeProbability<T>();
    o.lobes = static_cast<ltc::analytic_lobes>(
        in.ConsumeIntegralInRange<int>(0, static_cast<int>(ltc::analytic_lobes::cosine_lobe)));
    // Or a first-hit callback: every other query unoccluded (+inf), the others an occluder at any
    // multiple of the distance (negative, beyond the light, or overflowing to +inf included).
    const bool first_hit = in.ConsumeBool();
    const T hit_fraction = in.ConsumeFloatingPoint<T>();
    const auto occluder_at = [&](const vec3&, const vec3&, T distance) {
        return (queries++ & 1u) == 0 ? std::numeric_limits<T>::infinity() : distance * hit_fraction;
    };
    const auto shade = [&](const auto& callback) {
        return ltc::shade_polygon_light_shadowed(s.P, s.N, s.V, s.roughness, vec3(T(0.04)), vec3(T(0.5)), vec3(T(1)),
                                                 sc.v.data(), sc.v.size(), ltc::sidedness::one_sided, callback, o);
    };
    const auto r = first_hit ? shade(ltc::first_hit(occluder_at)) : shade(alternate);
    require_shadowed_in_range(r, first_hit);
    // The same plan through ltc::shade_shadowed<Model>, the model by o.lobes, the light one-sided
    // towards a side of its vector area (the light then walks the vertices reversed or not).
    const ltc::shadow_sampling<T>& plan = o;
    const bool back = in.ConsumeBool();
    switch (o.lobes) {
        case ltc::analytic_lobes::two:
            check_shade_shadowed<ltc::ggx::two_lobes>(sc, s, plan, back, first_hit, hit_fraction);
            break;
        case ltc::analytic_lobes::cosine_lobe:
            check_shade_shadowed<ltc::ggx::ltc_and_cosine>(sc, s, plan, back, first_hit, hit_fraction);
            break;
        default:
            check_shade_shadowed<ltc::ggx::one_lobe>(sc, s, plan, back, first_hit, hit_fraction);
            break;
    }
}

// Anisotropic GGX (ltc::ggx::anisotropic) with any finite tangent (zero, along N, huge or tiny
// included) and second roughness: the polygon light with one horizon-clipping strategy, or (`lanes`,
// where the polygon has four vertices or more) a quad light (its first four) 17 times over the
// point through batch::shade's lanes with one instruction set: finite.
template <typename T>
void check_anisotropic(FuzzedDataProvider& in, const std::vector<glm::vec<3, T>>& v, const shading_point<T>& s,
                       ltc::horizon_clipping clip, ltc::batch::isa isa, bool lanes) {
    using vec3 = glm::vec<3, T>;
    const vec3 tangent(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    const ltc::surface<T> a{s.P, s.N, s.V, s.roughness, vec3(T(0.04)), vec3(T(0.5)), tangent, in.ConsumeProbability<T>()};
    const std::size_t n = v.size();
    if (n == 0) return;
    if (!lanes || n < 4) {
        const auto r = ltc::shade<ltc::ggx::anisotropic>(a, ltc::polygon_light<T>::two_sided(v.data(), n, vec3(T(1))),
                                                         ltc::shade_options{clip});
        require_finite(r.specular, "anisotropic GGX specular");
        require_finite(r.diffuse, "anisotropic GGX diffuse");
        return;
    }
    constexpr std::size_t count = batch_results<T>::count;
    std::vector<T> q[12];
    for (std::size_t j = 0; j < count; ++j)
        for (int k = 0; k < 4; ++k) q[k].push_back(v[k].x), q[4 + k].push_back(v[k].y), q[8 + k].push_back(v[k].z);
    const T* x[4] = {q[0].data(), q[1].data(), q[2].data(), q[3].data()};
    const T* y[4] = {q[4].data(), q[5].data(), q[6].data(), q[7].data()};
    const T* z[4] = {q[8].data(), q[9].data(), q[10].data(), q[11].data()};
    batch_results<T> res;
    ltc::batch::shade<ltc::ggx::anisotropic>(
        a, ltc::batch::polygon_lights<T, 4>::two_sided(count, x, y, z, ltc::batch::uniform(vec3(T(1)))), res.out, isa);
    res.require_finite("anisotropic GGX batch over lights");
}

template <typename T>
void run(FuzzedDataProvider& in) {
    const scene<T> sc = read_scene<T>(in);
    const shading_point<T> s = read_shading_point<T>(in);
    // One part per input (a fuzzed byte): a point's shading and its shadows, batch shading, the
    // batch integrals, or anisotropic GGX. Each costs about as much as the others; run together, they made an input
    // costly (the harness's own work, and libFuzzer's per-edge bookkeeping of all their code).
    const unsigned part = in.ConsumeIntegral<std::uint8_t>() % 4u;
    if (part == 2) {
        check_batch<T>(in, sc.m, sc.v);
        return;
    }
    // Then the choices: bits 0-1 the horizon clipping, bits 2-3 the batch shading's instruction
    // set (of all of them: one this CPU lacks falls back to the next narrower one), bits 4-5 its
    // lobes, bit 6 the quad light's batch (where the polygon has four vertices or more) or the
    // point's.
    const unsigned choice = in.ConsumeIntegral<std::uint8_t>();
    if (part == 0) {
        constexpr ltc::horizon_clipping clips[] = {ltc::horizon_clipping::ltc_space,
                                                   ltc::horizon_clipping::shading_first,
                                                   ltc::horizon_clipping::sphere_analytic,
                                                   ltc::horizon_clipping::sphere_table};
        check_point_shading<T>(sc.v, s, clips[choice & 3u]);
        check_shadowed<T>(in, sc, s);
        return;
    }
    const ltc::batch::isa isa =
        ltc::batch::instruction_sets[((choice >> 2) & 3u) % std::size(ltc::batch::instruction_sets)];
    if (part == 3) {
        constexpr ltc::horizon_clipping clips[] = {ltc::horizon_clipping::ltc_space,
                                                   ltc::horizon_clipping::shading_first,
                                                   ltc::horizon_clipping::sphere_analytic,
                                                   ltc::horizon_clipping::sphere_table};
        check_anisotropic<T>(in, sc.v, s, clips[choice & 3u], isa, (choice & 64u) != 0u);
        return;
    }
    const int lobes = 1 + int(((choice >> 4) & 3u) % 3u);
    if ((choice & 64u) != 0u && sc.v.size() >= 4)
        check_quad_light_batch<T>(sc.v, s, isa, lobes);
    else
        check_point_batch<T>(sc.v, s, isa, lobes);
}

}  // namespace

LTC_FUZZ_ENTRY(run)
