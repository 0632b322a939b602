// ggx_error_report/breakdowns.cpp -- sections 2, 3 and 5 of the report: the relative errors by
// roughness, by view angle, and by placement and size.
#include "grid.hpp"
#include "ltc_estimate.hpp"
#include "report.hpp"
#include "statistics.hpp"

#include <cstdio>
#include <vector>

namespace ggx_error_report {

void print_by_roughness_and_view(const std::vector<config>& grid, const evaluation& ev) {
    std::printf("\n2. By roughness (alpha = roughness^2): mean / p95 / max relative error\n");
    std::printf("  %-9s", "roughness");
    for (int m = 0; m < method_count; ++m) std::printf(" | %-22s", method_names[m]);
    std::printf("\n");
    for (int r = 0; r < 5; ++r) {
        std::printf("  %-9.2f", roughnesses[r]);
        for (int m = 0; m < method_count; ++m) {
            const stats s = summarize(rel_errors(grid, ev, m, [&](const config& c) { return c.rough == r; }));
            std::printf(" | %5.1f%% %6.1f%% %7.1f%%", 100 * s.mean, 100 * s.p95, 100 * s.max);
        }
        std::printf("\n");
    }
    std::printf("\n3. By view angle\n");
    for (int t = 0; t < 4; ++t) {
        std::printf("  theta_v %2.0f", thetas[t]);
        for (int m = 0; m < method_count; ++m) {
            const stats s = summarize(rel_errors(grid, ev, m, [&](const config& c) { return c.theta == t; }));
            std::printf(" | %5.1f%% %6.1f%% %7.1f%%", 100 * s.mean, 100 * s.p95, 100 * s.max);
        }
        std::printf("\n");
    }
}

void print_by_placement_and_size(const std::vector<config>& grid, const evaluation& ev) {
    std::printf("\n5. By placement and size (exact | clip-first | sphere)\n");
    for (int pl = 0; pl < 4; ++pl)
        for (int sz = 0; sz < 3; ++sz) {
            char label[64];
            std::snprintf(label, sizeof label, "%-6s s/d=%.1f", placement_names[pl], sizes[sz]);
            std::printf("  %-15s", label);
            for (int m : {int(exact), int(clip_first), int(sphere)}) {
                const stats s = summarize(rel_errors(grid, ev, m, [&](const config& c) { return c.placement == pl && c.size == sz; }));
                std::printf(" | %5.1f%% %6.1f%% %7.1f%%", 100 * s.mean, 100 * s.p95, 100 * s.max);
            }
            std::printf("\n");
        }
}

}  // namespace ggx_error_report
