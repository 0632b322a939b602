// ggx_error_report/horizon.cpp -- section 4 of the report: lights entirely above vs partly below
// the horizon, the clip order on the straddling ones, and lights entirely below it.
#include "grid.hpp"
#include "ltc_estimate.hpp"
#include "report.hpp"
#include "statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <vector>

namespace ggx_error_report {

void print_horizon(const std::vector<config>& grid, const evaluation& ev, const fetch_fn& shipped) {
    std::printf("\n4. Lights entirely above vs partly below the horizon (mean / p95 / max relative error)\n");
    for (int below = 0; below < 2; ++below) {
        std::printf("  %-11s", below ? "straddling" : "above");
        for (int m = 0; m < method_count; ++m) {
            const stats s = summarize(rel_errors(grid, ev, m, [&](const config& c) { return c.straddles == bool(below); }));
            std::printf(" | %5.1f%% %6.1f%% %7.1f%%", 100 * s.mean, 100 * s.p95, 100 * s.max);
        }
        std::printf("\n");
    }
    std::printf("\n   Clip order on the straddling configurations, by view angle: mean signed relative error\n"
                "   (LTC - GT) / GT (the bias), mean |error|, and how often clip-first is the closer one\n");
    std::printf("  %-10s %5s | %-26s | %-26s | %-26s | %s\n", "theta_v", "n", "exact: bias  mean|e|", "clip-first: bias  mean|e|",
                "clip-once: bias  mean|e|", "clip-first closer");
    for (int t = -1; t < 4; ++t) {
        double bias[method_count] = {}, mean_abs[method_count] = {};
        std::size_t n = 0, closer = 0;
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const auto& c = grid[i];
            if (!c.straddles || !significant(c, ev.albedo[i]) || (t >= 0 && c.theta != t)) continue;
            ++n;
            for (int m = 0; m < method_count; ++m) {
                const double e = (ev.value[m][i] - c.gt.mean) / c.gt.mean;
                bias[m] += e;
                mean_abs[m] += std::abs(e);
            }
            closer += std::abs(ev.value[clip_first][i] - c.gt.mean) < std::abs(ev.value[exact][i] - c.gt.mean);
        }
        if (n == 0) continue;
        char label[32];
        std::snprintf(label, sizeof label, t < 0 ? "all" : "%.0f deg", t < 0 ? 0.0 : thetas[t]);
        std::printf("  %-10s %5zu |", label, n);
        for (int m : {int(exact), int(clip_first), int(clip_once)})
            std::printf(" %+8.2f%% %8.2f%%        |", 100 * bias[m] / double(n), 100 * mean_abs[m] / double(n));
        std::printf(" %zu of %zu\n", closer, n);
    }
    {
        double worst = 0;
        for (std::size_t i = 0; i < grid.size(); ++i)
            if (significant(grid[i], ev.albedo[i]))
                worst = std::max(worst, std::abs(ev.value[clip_once][i] - ev.value[clip_first][i]) / grid[i].gt.mean);
        std::printf("  clip-once vs clip-first (the second clip, in LTC space): max difference %.3f%% of GT\n", 100 * worst);
    }
    {
        // Lights entirely below the horizon (GT = 0): what the exact order lets leak through.
        // A 2:1 rectangle of half-diagonal s/d = 0.15 centred at elevation -10 deg, azimuth
        // 0 (the view side) or 180 (the mirror side).
        double worst[2] = {0, 0};
        int worst_t[2] = {0, 0}, worst_r[2] = {0, 0};
        for (int t = 0; t < 4; ++t)
            for (int r = 0; r < 5; ++r)
                for (int side = 0; side < 2; ++side) {
                    const double az = side ? 180 * deg : 0.0, el = -10 * deg;
                    config c{t, r, 0, 0, 0, {}, true, {}};
                    c.vertices = make_light(0, 0.15, dvec3(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)));
                    const double albedo = part_scale(shipped(std::cos(thetas[t] * deg), roughnesses[r]));
                    const double leak = ltc_estimate(c, shipped, exact) / albedo;
                    if (leak > worst[side]) worst[side] = leak, worst_t[side] = t, worst_r[side] = r;
                    if (ltc_estimate(c, shipped, clip_first) != 0.0) std::printf("  (clip-first leaked: a bug)\n");
                }
        std::printf("  lights entirely below the horizon (GT = 0), exact order: LTC / albedo up to %.2e (view side, theta_v %.0f,\n"
                    "  roughness %.2f) and %.2e (mirror side, theta_v %.0f, roughness %.2f); clip-first: exactly 0\n",
                    worst[0], thetas[worst_t[0]], roughnesses[worst_r[0]], worst[1], thetas[worst_t[1]], roughnesses[worst_r[1]]);
    }
}

}  // namespace ggx_error_report
