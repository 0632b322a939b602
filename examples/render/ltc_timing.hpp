// render/ltc_timing.hpp -- the LTC render of the polygonal lights, timed (each part the best of 5
// runs: it takes milliseconds): point by point, and a row of pixels at a time through the batch
// API (SIMD lanes), with the largest difference between the two; and the printed LTC times (with
// the textured light's, by each method with --textured-method all). With --lobes 1 or 2 both
// renders use that table (the model ltc::ggx::one_lobe or two_lobes). The library's lights are
// built once (ltc_lights) for every pixel and run.
#pragma once

#include "camera.hpp"
#include "common/threads.hpp"
#include "math.hpp"
#include "scene.hpp"
#include "shade_ltc.hpp"
#include "textured_methods.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace render {

/// The polygonal lights' LTC render and its times.
struct ltc_timing {
    int lobes = 3;  // --lobes: the LTC table of the polygonal lights (3: cosine, the default)
    std::vector<dvec3> poly;  // point by point: the polygonal lights (and their emitters)
    double seconds = INFINITY;  // point by point, best of 5
    double batch_seconds = INFINITY;  // through ltc::batch::shade<Model> (Model: --lobes'), best of 5
    double batch_diff = 0;  // largest difference of a channel, batch against point by point
    double peak = 0;  // largest floor value of a channel, point by point (with the batch part)
};

inline ltc_timing render_ltc_polygons(const scene& s, const std::vector<pixel_hit>& hits, int W, int H,
                                      unsigned threads, int lobes) {
    const std::size_t count = static_cast<std::size_t>(W) * H;
    ltc_timing t;
    t.lobes = lobes;
    t.poly.resize(count);
    const std::vector<ltc::polygon_light<float>> lights = ltc_lights(s);  // once, for every pixel and run
    for (int run = 0; run < 5; ++run) {
        const auto t0 = clock_type::now();
        for_each_row(H, threads, [&](int y) {
            for (int x = 0; x < W; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * W + x;
                t.poly[i] = dvec3(shade_ltc(s, lights, hits[i], lobes));
            }
        });
        t.seconds = std::min(t.seconds, seconds_since(t0));
    }
    // The same polygonal lights a row of pixels at a time through the batch API (SIMD lanes).
    std::vector<dvec3> ltc_batch(count);
    for (int run = 0; run < 5; ++run) {
        const auto t0 = clock_type::now();
        for_each_row(H, threads, [&](int y) {
            const std::size_t row = static_cast<std::size_t>(y) * W;
            std::vector<vec3> px(static_cast<std::size_t>(W));
            shade_ltc_batch(s, lights, hits.data() + row, px.size(), px.data(), lobes);
            for (int x = 0; x < W; ++x) ltc_batch[row + x] = dvec3(px[static_cast<std::size_t>(x)]);
        });
        t.batch_seconds = std::min(t.batch_seconds, seconds_since(t0));
    }
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c) {
            t.batch_diff = std::max(t.batch_diff, std::abs(ltc_batch[i][c] - t.poly[i][c]));
            if (hits[i].kind == pixel_hit::floor) t.peak = std::max(t.peak, t.poly[i][c]);
        }
    return t;
}

/// Prints the LTC render's times: in all (the polygonal lights and, with it, the textured light
/// of ltc.png, named by `method_note`), through the batch API, and with more than one run
/// (--textured-method all) the textured light by each method.
inline void print_ltc_times(const scene& s, const ltc_timing& t, const std::vector<textured_run>& runs,
                            const std::string& method_note, std::size_t floor_pixels, unsigned threads) {
    const double ltc_seconds = t.seconds, ltc_tex_seconds = textured_seconds(runs);
    if (!s.textured) {
        std::printf("LTC render:       %9.4f s  (best of 5; %.0f ns of one thread per floor pixel and light%s)\n",
                    ltc_seconds, ltc_seconds * 1e9 * threads / (static_cast<double>(floor_pixels) * s.lights.size()),
                    lobes_note(t.lobes));
    } else {
        std::printf("LTC render:       %9.4f s  (best of 5 of each part: polygonal lights%s %.4f s, %.0f ns of one "
                    "thread per floor pixel and light;\n"
                    "                                textured light%s %.4f s, %.0f ns per floor pixel)\n",
                    ltc_seconds + ltc_tex_seconds, lobes_note(t.lobes), ltc_seconds,
                    ltc_seconds * 1e9 * threads / (static_cast<double>(floor_pixels) * s.lights.size()),
                    method_note.c_str(), ltc_tex_seconds,
                    ltc_tex_seconds * 1e9 * threads / static_cast<double>(floor_pixels));
    }

    std::printf("LTC render, batch: %9.4f s  (the polygonal lights through ltc::batch::shade<ltc::ggx::%s>: %.1fx "
                "as fast;\n                                largest difference to the point-by-point render %.1e, "
                "floor values up to %.2f)\n",
                t.batch_seconds, t.lobes == 1 ? "one_lobe" : t.lobes == 2 ? "two_lobes" : "ltc_and_cosine",
                ltc_seconds / t.batch_seconds, t.batch_diff, t.peak);
    if (runs.size() > 1) print_method_times(runs, floor_pixels, threads);
}

}  // namespace render
