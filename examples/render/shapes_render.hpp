// render/shapes_render.hpp -- the --shapes section: the floor lit by the disk, sphere and tube
// lights of shapes.hpp alone, rendered apart from the rest (the default images and numbers do not
// change): the LTC render (each shape timed, best of 5) into shapes_ltc.png, the Monte Carlo
// reference (--spp / 2 iterations per pixel, shape and integral) into shapes_reference.png, the
// false colour of the relative error of luminance (as error.png) into shapes_error.png, and the
// statistics of error_stats.hpp: the three shapes together, then each shape alone.
#pragma once

#include "camera.hpp"
#include "common/colour.hpp"
#include "common/image.hpp"
#include "common/threads.hpp"
#include "error_stats.hpp"
#include "math.hpp"
#include "options.hpp"
#include "scene.hpp"
#include "shade_reference.hpp"
#include "shapes.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace render {

/// Iterations of the shapes' reference per pixel, shape and integral: half of --spp.
inline int shapes_spp(const options& opt) { return opt.spp > 0 ? std::max(1, opt.spp / 2) : 0; }

/// Renders, writes and reports the --shapes section; returns false if an image could not be
/// written or a value was not finite.
inline bool run_shapes(const scene& s, const std::vector<pixel_hit>& hits, std::size_t floor_pixels,
                       const options& opt, const std::filesystem::path& out_dir) {
    const int W = opt.width, H = opt.height;
    const std::size_t count = static_cast<std::size_t>(W) * H;
    const shape_lights L;
    constexpr int K = shape_lights::count;
    std::vector<dvec3> ltc[K], ref[K];
    std::vector<double> var[K];
    double seconds[K];
    for (int k = 0; k < K; ++k) {
        ltc[k].assign(count, dvec3(0.0));
        seconds[k] = INFINITY;
        for (int run = 0; run < 5; ++run) {
            const auto t0 = clock_type::now();
            for_each_row(H, opt.threads, [&](int y) {
                for (int x = 0; x < W; ++x) {
                    const std::size_t i = static_cast<std::size_t>(y) * W + x;
                    ltc[k][i] = dvec3(shade_ltc_shape(s, L, hits[i], k));
                }
            });
            seconds[k] = std::min(seconds[k], seconds_since(t0));
        }
    }
    std::size_t ltc_nonfinite = 0, ref_nonfinite = 0;
    std::vector<dvec3> ltc_all(count, dvec3(0.0)), ref_all(count, dvec3(0.0));
    for (int k = 0; k < K; ++k)
        for (std::size_t i = 0; i < count; ++i) {
            if (!finite3(ltc[k][i])) ++ltc_nonfinite, ltc[k][i] = dvec3(0.0);
            ltc_all[i] += ltc[k][i];
        }
    std::vector<std::uint8_t> rgb(count * 3);
    for (std::size_t i = 0; i < count; ++i) tone_map(ltc_all[i], opt.exposure, &rgb[3 * i]);
    bool ok = write_png(out_dir / "shapes_ltc.png", W, H, rgb);

    std::printf("\n=== --shapes: the floor lit by a disk, a sphere and a tube light alone (shapes_ltc.png, "
                "shapes_reference.png, shapes_error.png) ===\n");
    std::printf("shapes LTC render: %8.4f s  (best of 5 of each shape, ns of one thread per floor pixel:", 
                seconds[0] + seconds[1] + seconds[2]);
    for (int k = 0; k < K; ++k)
        std::printf("%s %s %.0f", k ? "," : "", L.names[k],
                    seconds[k] * 1e9 * opt.threads / static_cast<double>(floor_pixels));
    std::printf(")\n");
    const int spp = shapes_spp(opt);
    if (spp == 0) {
        std::printf("non-finite values (shapes): LTC %zu\n", ltc_nonfinite);
        return ok && ltc_nonfinite == 0;
    }

    // Reference: every pixel and shape with its own seeds (independent of the thread count).
    std::fflush(stdout);  // the progress bar goes to stderr
    for (int k = 0; k < K; ++k) ref[k].assign(count, dvec3(0.0)), var[k].assign(count, 0.0);
    std::vector<long long> row_cost(static_cast<std::size_t>(H), 0);
    for (std::size_t i = 0; i < count; ++i)
        row_cost[i / static_cast<std::size_t>(W)] += hits[i].kind == pixel_hit::floor;
    const std::uint64_t base = mix_seed(opt.seed, 0x5348415045530000ull);  // apart from the polygons' seeds
    const auto t0 = clock_type::now();
    for_each_row(
        H, opt.threads,
        [&](int y) {
            for (int x = 0; x < W; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * W + x;
                const std::uint64_t pixel_seed = mix_seed(base, i);
                for (int k = 0; k < K; ++k) {
                    const shape_reference_pixel p = shade_reference_shape(
                        s, L, hits[i], k, mix_seed(pixel_seed, static_cast<std::uint64_t>(k)), spp);
                    ref[k][i] = p.radiance;
                    var[k][i] = p.variance;
                }
            }
        },
        "shapes reference", &row_cost);
    const double ref_seconds = seconds_since(t0);
    std::vector<double> var_all(count, 0.0);
    for (int k = 0; k < K; ++k)
        for (std::size_t i = 0; i < count; ++i) {
            if (!finite3(ref[k][i]) || !std::isfinite(var[k][i])) ++ref_nonfinite, ref[k][i] = dvec3(0.0), var[k][i] = 0;
            ref_all[i] += ref[k][i];
            var_all[i] += var[k][i];  // independent seeds
        }
    for (std::size_t i = 0; i < count; ++i) tone_map(ref_all[i], opt.exposure, &rgb[3 * i]);
    ok = write_png(out_dir / "shapes_reference.png", W, H, rgb) && ok;
    std::printf("shapes reference: %9.4f s  (%d iterations x 2 directions x 2 or 3 integrals (A, B; diffuse where "
                "albedo > 0)\n                                per pixel and shape, %u threads)\n",
                ref_seconds, spp, opt.threads);
    std::printf("reference / LTC:  %9.0f x\n", ref_seconds / (seconds[0] + seconds[1] + seconds[2]));

    const double floor = dark_floor / opt.exposure;
    const error_stats all = measure_error(hits, ltc_all, ref_all, var_all, floor, rgb);
    ok = write_png(out_dir / "shapes_error.png", W, H, rgb) && ok;
    std::printf("\n");
    print_error(s, all, floor, "Y_ref,shapes");
    std::vector<std::uint8_t> scratch(count * 3);
    std::printf("\neach shape alone (its contribution, over the floor pixels with its own Y_ref >= %.3g):\n", floor);
    for (int k = 0; k < K; ++k) {
        const error_stats st = measure_error(hits, ltc[k], ref[k], var[k], floor, scratch);
        std::printf("  %-6s %6zu px  mean %.2f%%  median %.2f%%  p95 %.2f%%  max %.2f%%  (mean signed %+.2f%%)  "
                    "noise mean %.2f%% p95 %.2f%%  > 3 s.e. %.1f%%\n",
                    L.names[k], st.rel.size(), 100 * mean_of(st.rel), 100 * percentile(st.rel, 0.5),
                    100 * percentile(st.rel, 0.95), 100 * percentile(st.rel, 1.0), 100 * mean_of(st.signed_rel),
                    100 * mean_of(st.noise), 100 * percentile(st.noise, 0.95),
                    st.rel.empty() ? 0.0 : 100.0 * static_cast<double>(st.significant) / static_cast<double>(st.rel.size()));
    }
    std::printf("non-finite values (shapes): LTC %zu, reference %zu\n", ltc_nonfinite, ref_nonfinite);
    return ok && ltc_nonfinite == 0 && ref_nonfinite == 0;
}

}  // namespace render
