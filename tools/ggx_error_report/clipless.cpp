// ggx_error_report/clipless.cpp -- section 6 of the report: the clipless methods (sphere,
// sphere-tab) against exact LTC clipping with the same table.
#include "grid.hpp"
#include "ltc_estimate.hpp"
#include "report.hpp"
#include "statistics.hpp"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <vector>

namespace ggx_error_report {

void print_clipless_vs_exact(const std::vector<config>& grid, const evaluation& ev) {
    std::printf("\n6. Clipless vs exact LTC clipping (same table): |sphere - exact| / exact, the cost of the sphere\n"
                "   approximation alone, on the straddling configurations and on all (it is exact when M^-1 P and\n"
                "   its sphere are both above the LTC's horizon, which an elongated M^-1 P often is not)\n");
    for (int m : {int(sphere), int(sphere_tab)}) {
        for (int r = -1; r < 5; ++r) {
            std::vector<double> e, e_all;
            for (std::size_t i = 0; i < grid.size(); ++i) {
                if (r >= 0 && grid[i].rough != r) continue;
                const double x = ev.value[exact][i];
                if (!(x >= 1e-3 * ev.albedo[i])) continue;
                const double d = std::abs(ev.value[m][i] - x) / x;
                e_all.push_back(d);
                if (grid[i].straddles) e.push_back(d);
            }
            char label[64];
            if (r < 0)
                std::snprintf(label, sizeof label, "%s all", method_names[m]);
            else
                std::snprintf(label, sizeof label, "%s r=%.2f", method_names[m], roughnesses[r]);
            const stats s = summarize(e), sa = summarize(e_all);
            std::printf("  %-18s straddling n=%3zu mean %6.2f%% p95 %6.2f%% max %7.2f%% | all n=%3zu max %7.2f%%\n", label,
                        s.count, 100 * s.mean, 100 * s.p95, 100 * s.max, sa.count, 100 * sa.max);
        }
    }
    {
        double worst = 0;
        std::size_t wi = 0;
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const double x = ev.value[exact][i];
            if (!(x >= 1e-3 * ev.albedo[i])) continue;
            const double d = std::abs(ev.value[sphere][i] - x) / x;
            if (d > worst) worst = d, wi = i;
        }
        const auto& c = grid[wi];
        std::printf("  worst sphere case: theta_v %.0f, roughness %.2f, %s, s/d %.1f, %s: exact %.4g sphere %.4g GT %.4g\n",
                    thetas[c.theta], roughnesses[c.rough], shape_names[c.shape], sizes[c.size], placement_names[c.placement],
                    ev.value[exact][wi], ev.value[sphere][wi], c.gt.mean);
    }
}

}  // namespace ggx_error_report
