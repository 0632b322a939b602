// render/textured_methods.hpp -- the textured light by each method of --textured-method (one, or
// all three with "all"): a run per method (its ltc::textured_policy and label), the LTC render
// of the textured light's contribution by each (timed, best of 5), and with "all" each method's
// time and, next to the others', its statistics against the one reference.
#pragma once

#include "camera.hpp"
#include "common/threads.hpp"
#include "error_stats.hpp"
#include "math.hpp"
#include "options.hpp"
#include "scene.hpp"
#include "shade_ltc.hpp"

#include <ltc/shading/lights/textured_quad_light.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace render {

/// The textured light's LTC render by one method (--textured-method).
struct textured_run {
    ltc::textured_policy policy;
    std::string label;  // "fetch", "quick_cells", "exact_cells (N cells)"
    std::vector<dvec3> ltc;  // its contribution (and its emitter)
    double seconds = INFINITY;  // best of 5
};

/// A run, its image black, for each method of --textured-method (one, or all three with "all");
/// none without the textured light. The first one's is the textured light of ltc.png, error.png
/// and textured_error.png (fetch's with "all").
inline std::vector<textured_run> make_textured_runs(const options& opt, bool textured, std::size_t count) {
    std::vector<textured_run> runs;
    for (std::size_t k = 0; textured && k < opt.textured_methods.size(); ++k) {
        textured_run r;
        r.policy.method = opt.textured_methods[k];
        r.policy.budget.max_cells = opt.cells;
        r.label = method_name(r.policy.method);
        if (r.policy.method == ltc::textured_method::exact_cells) r.label += " (" + std::to_string(opt.cells) + " cells)";
        r.ltc.assign(count, dvec3(0.0));
        runs.push_back(std::move(r));
    }
    return runs;
}

/// " by exact_cells (64 cells)" after "textured light" where the method is named: with all, or
/// with one method other than the default fetch (the default run's lines are left as they were).
inline std::string method_note(const std::vector<textured_run>& runs) {
    const bool compare = runs.size() > 1;  // --textured-method all
    return !runs.empty() && (compare || runs[0].policy.method != ltc::textured_method::fetch) ? " by " + runs[0].label
                                                                                               : "";
}

/// The LTC time of the textured light in ltc.png (the first run's; 0 without the textured light).
inline double textured_seconds(const std::vector<textured_run>& runs) {
    return runs.empty() ? 0.0 : runs[0].seconds;
}

/// Each run's LTC render of the textured light (its ltc::textured_quad_light built once), timed as
/// the best of 5 runs; runs is empty without the textured light (make_textured_runs).
inline void render_textured_runs(const scene& s, const std::vector<pixel_hit>& hits, int W, int H, unsigned threads,
                                 std::vector<textured_run>& runs) {
    for (textured_run& r : runs) {
        const ltc::textured_quad_light<float> light = ltc_textured_light(*s.textured, r.policy);  // once per method
        for (int run = 0; run < 5; ++run) {
            const auto t0 = clock_type::now();
            for_each_row(H, threads, [&](int y) {
                for (int x = 0; x < W; ++x) {
                    const std::size_t i = static_cast<std::size_t>(y) * W + x;
                    r.ltc[i] = dvec3(shade_ltc_textured(s, light, hits[i]));
                }
            });
            r.seconds = std::min(r.seconds, seconds_since(t0));
        }
    }
}

/// --textured-method all: each method's LTC time for the textured light and its ratio to fetch's.
inline void print_method_times(const std::vector<textured_run>& runs, std::size_t floor_pixels, unsigned threads) {
    std::printf("LTC render, the textured light by each method (best of 5 each; ltc_<method>.png):\n");
    for (const textured_run& r : runs)
        std::printf("  %-24s %9.4f s  %7.0f ns of one thread per floor pixel  %6.1fx the time of fetch\n",
                    r.label.c_str(), r.seconds, r.seconds * 1e9 * threads / static_cast<double>(floor_pixels),
                    r.seconds / runs[0].seconds);
}

/// --textured-method all: the textured light's statistics of every method side by side (the same
/// reference and floor pixels for all): LTC time and error of luminance, then the per-tile means.
inline void print_comparison(const scene& s, const std::vector<textured_run>& runs, const std::vector<error_stats>& st,
                             std::size_t floor_pixels, unsigned threads) {
    std::printf("\n=== the textured light alone, the methods side by side (the same reference, the same %zu floor "
                "pixels) ===\n",
                st[0].rel.size());
    std::printf("  %-24s %10s %9s   |relative error|: %6s %7s %7s %7s   %7s %8s\n", "method", "LTC time", "ns/pixel",
                "mean", "median", "p95", "max", "signed", ">3 s.e.");
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const error_stats& e = st[k];
        std::printf("  %-24s %8.4f s %9.0f   %16s %5.2f%% %6.2f%% %6.2f%% %6.1f%%   %+6.2f%% %7.1f%%\n",
                    runs[k].label.c_str(), runs[k].seconds,
                    runs[k].seconds * 1e9 * threads / static_cast<double>(floor_pixels), "", 100 * mean_of(e.rel),
                    100 * percentile(e.rel, 0.5), 100 * percentile(e.rel, 0.95), 100 * percentile(e.rel, 1.0),
                    100 * mean_of(e.signed_rel),
                    e.rel.empty() ? 0.0 : 100.0 * static_cast<double>(e.significant) / static_cast<double>(e.rel.size()));
    }
    std::printf("  (LTC time: best of 5, %u thread%s; ns/pixel: of one thread per floor pixel; signed: mean signed\n"
                "  relative error; >3 s.e.: pixels where |Y_ltc - Y_ref| > 3 standard errors of the reference)\n",
                threads, threads == 1 ? "" : "s");
    std::printf("\nper tile, mean |relative error| in %%,");
    for (std::size_t k = 0; k < runs.size(); ++k)
        std::printf("%s%s", k ? " / " : " ", method_name(runs[k].policy.method));
    std::printf("; bands far to near, stripes left to right:\n  roughness");
    for (const char* name : s.column_names) std::printf(" %20s", name);
    std::printf("\n");
    for (int b = scene::bands - 1; b >= 0; --b) {
        std::printf("  %9.2f", static_cast<double>(s.roughness[b]));
        for (int c = 0; c < scene::columns; ++c) {
            const std::size_t m = static_cast<std::size_t>(b * scene::columns + c);
            std::string cell;
            for (std::size_t k = 0; k < runs.size(); ++k) {
                char v[24];
                if (st[k].tile_rel[m].empty())
                    std::snprintf(v, sizeof v, "-");
                else
                    std::snprintf(v, sizeof v, "%.1f", 100 * mean_of(st[k].tile_rel[m]));
                cell += (k ? " / " : "") + std::string(v);
            }
            std::printf(" %20s", cell.c_str());
        }
        std::printf("\n");
    }
}

}  // namespace render
