// libFuzzer harness: for any finite polygon (0..15 vertices, any magnitudes, degenerate or not)
// and any matrix accepted by the checked factory, every integral, density and sample of the
// library is finite; so is GGX polygon-light shading for any finite P, N, V and roughness, with one
// or two lobes or an LTC and the cosine, point by point and in batches (every instruction set
// this CPU runs), and with shadows (the ratio estimator and its two sums per term, any sample
// plan, any analytic part); the batch API (fuzz_batch.hpp: batches of 1..19 quads or n-gons
// with every instruction set this CPU runs) agrees with the scalar path; and the textured lights
// (fuzz_textured.hpp: tiny textures, the exact cell integrals with fuzzed budgets and
// tolerances, textured shading with every method) give finite results, non-negative for
// non-negative textures, with finite, non-negative error bounds; and the polygon samplers
// (fuzz_sampling.hpp: projected solid angle, restricted LTC, light area) give finite directions,
// densities and inverses. Build: clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined
// -I include tests/fuzz/fuzz_integrals.cpp; run on tests/fuzz/corpus (see .ci/run).
#include "fuzz_batch.hpp"
#include "fuzz_common.hpp"
#include "fuzz_sampling.hpp"
#include "fuzz_shapes.hpp"
#include "fuzz_textured.hpp"

#include <ltc/ltc.hpp>
#include <ltc/shading/clipless.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/shadowed_polygon_light.hpp>
#include <ltc/shading/batch_shading.hpp>
#include <ltc/shading/batch_cosine_lobe.hpp>
#include <ltc/shading/batch_two_lobe.hpp>
#include <ltc/shading/two_lobe_polygon_light.hpp>
#include <ltc/shading/cosine_lobe_polygon_light.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace {

// fuzz_common.hpp, fuzz_batch.hpp, fuzz_textured.hpp, fuzz_shapes.hpp, fuzz_sampling.hpp
using namespace ltc_fuzz;

template <typename T, typename Dist>
void check_distribution(const glm::vec<3, T>* v, std::size_t n, const glm::mat<3, 3, T>& m, bool use_inverse,
                        const glm::vec<2, T>& u) {
    require_finite(Dist::integrate(v, n), "D_o integral");
    try {
        const auto d = use_inverse ? ltc::transformed<Dist>::checked_from_inverse(m) : ltc::transformed<Dist>::checked(m);
        require_finite(d.integrate(v, n), "integral");
        require_finite(d.integrate(v, n, ltc::sidedness::one_sided), "one-sided integral");
        const glm::vec<3, T> w = d.sample(u);
        require_finite(w, "sample");
        const T p = d.pdf(w);
        require_finite(p, "pdf");
        if (!(p > T(0))) {
            std::fprintf(stderr, "sample with zero pdf\n");
            std::abort();
        }
        for (std::size_t i = 0; i < n; ++i) require_finite(d.eval(ltc::detail::safe_normalize(v[i])), "eval");
    } catch (const ltc::invalid_transform&) {
        // rejected matrices are the checked factory's job
    }
}

template <typename T>
void run(FuzzedDataProvider& in) {
    using vec3 = glm::vec<3, T>;
    glm::mat<3, 3, T> m;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) m[c][r] = finite_value<T>(in);
    const bool use_inverse = in.ConsumeBool();
    const T u0 = in.ConsumeProbability<T>(), u1 = in.ConsumeProbability<T>();
    const glm::vec<2, T> u(u0 < T(1) ? u0 : T(0), u1 < T(1) ? u1 : T(0));
    const std::size_t n = in.ConsumeIntegralInRange<std::size_t>(0, 15);
    std::vector<vec3> v(n);
    for (auto& p : v) p = vec3(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    const vec3* pv = v.data();

    require_finite(ltc::solid_angle(pv, n), "solid angle");
    require_finite(ltc::clipped_solid_angle(pv, n), "clipped solid angle");
    require_finite(ltc::form_factor_signed(pv, n), "form factor");
    const vec3 f = ltc::vector_form_factor(pv, n);
    require_finite(f, "vector form factor");
    std::vector<vec3> clipped(ltc::clipped_capacity(n));
    const std::size_t k = ltc::clip_to_horizon(pv, n, clipped.data());
    if (k > ltc::clipped_capacity(n)) std::abort();
    for (std::size_t i = 0; i < k; ++i) require_finite(clipped[i], "clipped vertex");

    // World-space GGX shading with every horizon-clipping strategy (P, N, V, roughness fuzzed).
    const vec3 P(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    const vec3 N(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    const vec3 V(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    const T roughness = in.ConsumeProbability<T>();
    for (const auto clip : {ltc::horizon_clipping::ltc_space, ltc::horizon_clipping::shading_first,
                            ltc::horizon_clipping::sphere_analytic, ltc::horizon_clipping::sphere_table}) {
        const auto r = ltc::shade_polygon_light_one_lobe(P, N, V, roughness, vec3(T(0.04)), vec3(T(0.5)), vec3(T(1)), pv,
                                                         n, ltc::sidedness::two_sided, clip);
        require_finite(r.specular, "GGX specular");
        require_finite(r.diffuse, "GGX diffuse");
        const auto r2 = ltc::shade_polygon_light_two_lobe(P, N, V, roughness, vec3(T(0.04)), vec3(T(0.5)), vec3(T(1)), pv, n,
                                                          ltc::sidedness::two_sided, clip);
        require_finite(r2.specular, "two-lobe GGX specular");
        require_finite(r2.diffuse, "two-lobe GGX diffuse");
        const auto r3 = ltc::shade_polygon_light_cosine_lobe(P, N, V, roughness, vec3(T(0.04)), vec3(T(0.5)), vec3(T(1)), pv,
                                                             n, ltc::sidedness::two_sided, clip);
        require_finite(r3.specular, "LTC and cosine GGX specular");
        require_finite(r3.diffuse, "LTC and cosine GGX diffuse");
        // The default is the LTC and the cosine (ltc/shading/polygon_light.hpp).
        const auto r0 = ltc::shade_polygon_light(P, N, V, roughness, vec3(T(0.04)), vec3(T(0.5)), vec3(T(1)), pv, n,
                                                 ltc::sidedness::two_sided, clip);
        if (!(r0.specular == r3.specular && r0.diffuse == r3.diffuse)) {
            std::fprintf(stderr, "the default shading differs from shade_polygon_light_cosine_lobe\n");
            std::abort();
        }
    }

    // The same point in the batch shading, one lobe, two lobes, an LTC and the cosine, with every
    // instruction set: 17 items
    // (full vectors and a tail at every width), roughness from the fuzzed one to 1.
    {
        constexpr std::size_t count = 17;
        std::vector<T> columns[16], results[6];
        for (int c = 0; c < 16; ++c) columns[c].assign(count, T(0));
        for (auto& r : results) r.assign(count, T(0));
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
        ltc::batch::shading_results<T> out;
        for (int c = 0; c < 3; ++c) out.specular[c] = results[c].data(), out.diffuse[c] = results[3 + c].data();
        for (const auto isa : ltc::batch::instruction_sets) {
            for (int lobes = 1; lobes <= 3; ++lobes) {
                if (lobes == 3)
                    ltc::batch::shade_polygon_light_cosine_lobe(points, vec3(T(1)), pv, n, ltc::sidedness::two_sided, out,
                                                                count, isa);
                else if (lobes == 1)
                    ltc::batch::shade_polygon_light_one_lobe(points, vec3(T(1)), pv, n, ltc::sidedness::two_sided, out, count,
                                                             isa);
                else
                    ltc::batch::shade_polygon_light_two_lobe(points, vec3(T(1)), pv, n, ltc::sidedness::two_sided, out,
                                                             count, isa);
                for (const auto& r : results)
                    for (const T x : r) require_finite(x, "batch GGX shading");
            }
            // A quad light (the fuzzed polygon's first four vertices) 17 times over one point,
            // through the quad-light batches of the three tables.
            if (n >= 4) {
                std::vector<T> q[15];
                for (std::size_t j = 0; j < count; ++j) {
                    for (int k = 0; k < 4; ++k)
                        q[k].push_back(pv[k].x), q[4 + k].push_back(pv[k].y), q[8 + k].push_back(pv[k].z);
                    for (int c = 0; c < 3; ++c) q[12 + c].push_back(T(1));
                }
                ltc::batch::quad_lights<T> lights;
                for (int k = 0; k < 4; ++k) lights.x[k] = q[k].data(), lights.y[k] = q[4 + k].data(), lights.z[k] = q[8 + k].data();
                for (int c = 0; c < 3; ++c) lights.radiance[c] = q[12 + c].data();
                const vec3 F0(T(0.04)), albedo(T(0.5));
                for (int lobes = 1; lobes <= 3; ++lobes) {
                    if (lobes == 1)
                        ltc::batch::shade_quad_lights_one_lobe(P, N, V, roughness, F0, albedo, lights,
                                                               ltc::sidedness::two_sided, out, count, isa);
                    else if (lobes == 2)
                        ltc::batch::shade_quad_lights_two_lobe(P, N, V, roughness, F0, albedo, lights,
                                                               ltc::sidedness::two_sided, out, count, isa);
                    else
                        ltc::batch::shade_quad_lights_cosine_lobe(P, N, V, roughness, F0, albedo, lights,
                                                                  ltc::sidedness::two_sided, out, count, isa);
                    for (const auto& r : results)
                        for (const T x : r) require_finite(x, "quad-light batch GGX shading");
                }
            }
        }
    }

    // Shadowed shading (the ratio estimator): any sample plan, one or two lobes; the visibility
    // alternates, so that both of each ratio's sums see samples.
    {
        std::size_t queries = 0;
        const auto alternate = [&](const vec3&, const vec3&, T) { return (queries++ & 1u) == 0; };
        ltc::shadow_options<T> o;
        o.samples = in.ConsumeIntegralInRange<std::size_t>(0, 8);
        o.rotation = u;
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
            return ltc::shade_polygon_light_shadowed(P, N, V, roughness, vec3(T(0.04)), vec3(T(0.5)), vec3(T(1)), pv, n,
                                                     ltc::sidedness::one_sided, callback, o);
        };
        const auto r = first_hit ? shade(ltc::first_hit(occluder_at)) : shade(alternate);
        require_finite(r.blockers.ratio_sum, "blockers' ratio sum");
        require_finite(ltc::penumbra_width(T(1), r.blockers), "penumbra width");
        if (!(r.blockers.ratio_sum >= T(0) && r.blockers.occluded <= T(r.rays) && (first_hit || r.blockers.occluded == T(0)))) {
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

    check_distribution<T, ltc::uniform_sphere<T>>(pv, n, m, use_inverse, u);
    check_distribution<T, ltc::uniform_hemisphere<T>>(pv, n, m, use_inverse, u);
    check_distribution<T, ltc::clamped_cosine<T>>(pv, n, m, use_inverse, u);
    check_distribution<T, ltc::squared_clamped_cosine<T>>(pv, n, m, use_inverse, u);

    check_batch<T>(in, m, v);
    check_textured<T>(in, m, v, P, N, V, roughness);
    check_shapes<T>(in, m, v, P, N, V, roughness);
    check_sampling<T>(in, m, v);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    if (in.ConsumeBool())
        run<float>(in);
    else
        run<double>(in);
    return 0;
}
