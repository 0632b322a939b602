// render/reference_render.hpp -- the reference render, timed: every pixel by shade_reference on the
// worker threads (its progress on stderr), split into the polygonal lights' and the
// textured light's radiance with the variances of their luminance (non-finite values counted and
// replaced by black), and its printed time.
#pragma once

#include "camera.hpp"
#include "common/threads.hpp"
#include "error_stats.hpp"
#include "math.hpp"
#include "options.hpp"
#include "scene.hpp"
#include "shade_reference.hpp"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <vector>

namespace render {

/// The reference render, per pixel.
struct reference_render {
    std::vector<dvec3> poly, tex, img;  // the polygonal lights, the textured light, both
    std::vector<double> var_poly, var_tex, var_all;  // the variances of their luminance
    std::size_t nonfinite = 0;  // non-finite values, replaced by black
    double seconds = 0;  // the render's time
};

inline reference_render render_reference(const scene& s, const std::vector<pixel_hit>& hits, int W, int H,
                                         const options& opt) {
    const std::size_t count = static_cast<std::size_t>(W) * H;
    std::fflush(stdout);  // the progress bar goes to stderr
    std::vector<reference_pixel> ref(count);
    const auto t0 = clock_type::now();
    std::vector<long long> row_cost(static_cast<std::size_t>(H), 0);  // floor pixels per row
    for (std::size_t i = 0; i < count; ++i)
        row_cost[i / static_cast<std::size_t>(W)] += hits[i].kind == pixel_hit::floor;
    for_each_row(
        H, opt.threads,
        [&](int y) {
            for (int x = 0; x < W; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * W + x;
                ref[i] = shade_reference(s, hits[i], mix_seed(opt.seed, i), opt.spp);
            }
        },
        "reference", &row_cost);
    reference_render r;
    r.seconds = seconds_since(t0);

    r.poly.resize(count), r.tex.resize(count), r.img.resize(count);
    r.var_poly.resize(count), r.var_tex.resize(count), r.var_all.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        reference_pixel& p = ref[i];
        if (!finite3(p.radiance) || !std::isfinite(p.luminance_variance))
            ++r.nonfinite, p.radiance = dvec3(0.0), p.luminance_variance = 0;
        if (!finite3(p.textured) || !std::isfinite(p.textured_variance))
            ++r.nonfinite, p.textured = dvec3(0.0), p.textured_variance = 0;
        r.poly[i] = p.radiance;
        r.tex[i] = p.textured;
        r.img[i] = p.radiance + p.textured;
        r.var_poly[i] = p.luminance_variance;
        r.var_tex[i] = p.textured_variance;
        r.var_all[i] = p.luminance_variance + p.textured_variance;  // independent seeds
    }
    return r;
}

/// Prints the reference render's time and its ratio to the LTC render's (`ltc_seconds`).
inline void print_reference_time(const scene& s, const reference_render& r, const options& opt, double ltc_seconds) {
    if (!s.textured)
        std::printf("reference render: %9.4f s  (%d iterations x 2 directions x 2 integrals per pixel and light, "
                    "%u threads)\n",
                    r.seconds, opt.spp, opt.threads);
    else
        std::printf("reference render: %9.4f s  (%d iterations x 2 directions x 2 integrals per pixel and polygonal "
                    "light,\n"
                    "                                x 1 or 2 integrals (specular; diffuse where albedo > 0) for the "
                    "textured light, %u threads)\n",
                    r.seconds, opt.spp, opt.threads);
    std::printf("reference / LTC:  %9.0f x\n", r.seconds / ltc_seconds);
}

}  // namespace render
