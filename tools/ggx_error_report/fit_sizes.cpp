// ggx_error_report/fit_sizes.cpp -- section 7 of the report: tables fitted here at smaller sizes
// (ltc::fit::fit_table), their fitting time and size, against the same ground truth.
#include "common/progress.hpp"
#include "grid.hpp"
#include "ltc_estimate.hpp"
#include "report.hpp"
#include "statistics.hpp"

#include <ltc/brdf/ggx.hpp>
#include <ltc/fitting/fit.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace ggx_error_report {

void print_fit_sizes(const std::vector<config>& grid, const evaluation& ev, const std::vector<int>& fit_sizes,
                     unsigned threads) {
    const auto any = [](const config&) { return true; };
    std::printf("\n7. Fit error vs table size and fitting time (ltc::fit::fit_table<ggx>, default options,\n"
                "   %u threads; exact clipping), relative error against the same ground truth\n", threads);
    std::printf("  %-8s %10s %10s | %7s %7s %8s | %s\n", "size", "bytes", "fit time", "mean", "p95", "max", "by roughness: mean");
    for (int n : fit_sizes) {
        ltc::fit::options fo;
        fo.size = n;
        fo.threads = threads;
        ltc_examples::progress shown("fit " + std::to_string(n) + "x" + std::to_string(n), "nodes");
        const auto t0 = std::chrono::steady_clock::now();
        const ltc::fit::table tab =
            ltc::fit::fit_table<ltc::brdf::ggx>(fo, [&](std::size_t d, std::size_t t) { shown.update(d, t); });
        const double secs = seconds_since(t0);
        const std::vector<float> data = tab.packed();
        const ltc::ltc_table view(data.data(), n, n);
        const fetch_fn f = [&](double c, double r) { return view.fetch<double>(c, r); };
        const evaluation e = evaluate(grid, f, false);
        const stats s = summarize(rel_errors(grid, e, exact, any));
        std::printf("  %2dx%-5d %10zu %9.2fs | %6.2f%% %6.2f%% %7.2f%% |", n, n, data.size() * sizeof(float), secs, 100 * s.mean,
                    100 * s.p95, 100 * s.max);
        for (int r = 0; r < 5; ++r)
            std::printf(" %5.1f%%", 100 * summarize(rel_errors(grid, e, exact, [&](const config& c) { return c.rough == r; })).mean);
        std::printf("\n");
    }
    {
        const stats s = summarize(rel_errors(grid, ev, exact, any));
        const int w = ltc::ggx::table.width(), h = ltc::ggx::table.height();
        std::printf("  %2dx%-5d %10zu %10s | %6.2f%% %6.2f%% %7.2f%% |", w, h, std::size_t(w) * h * 6 * sizeof(float), "shipped",
                    100 * s.mean, 100 * s.p95, 100 * s.max);
        for (int r = 0; r < 5; ++r)
            std::printf(" %5.1f%%", 100 * summarize(rel_errors(grid, ev, exact, [&](const config& c) { return c.rough == r; })).mean);
        std::printf("\n");
    }
}

}  // namespace ggx_error_report
