// ggx_error_report/objectives.cpp -- section 8 of the report: tables fitted here with each per-node
// objective of ltc::fit::options::goal (the paper's L3 distance, the integral objective of
// ltc/fitting/integral_objective.hpp, their sum; each optionally with a fitted magnitude scale),
// their fitting time, against the same ground truth and over the same significant
// configurations as section 1 (the significance threshold uses the shipped table's albedo, so
// that a fitted magnitude does not change the set).
#include "grid.hpp"
#include "ltc_estimate.hpp"
#include "report.hpp"
#include "statistics.hpp"

#include <ltc/fitting/brdf/ggx.hpp>
#include <ltc/fitting/fit.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/table.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace ggx_error_report {

namespace {

void print_row(const char* label, const char* time, const std::vector<config>& grid, const evaluation& e) {
    const auto any = [](const config&) { return true; };
    const stats s = summarize(rel_errors(grid, e, exact, any));
    const stats s80 = summarize(rel_errors(grid, e, exact, [](const config& c) { return c.theta == 3; }));
    std::printf("  %-16s %9s | %6.2f%% %6.2f%% %7.2f%% | %6.2f%% |", label, time, 100 * s.mean, 100 * s.p95, 100 * s.max,
                100 * s80.mean);
    for (int r = 0; r < 5; ++r)
        std::printf(" %5.1f%%", 100 * summarize(rel_errors(grid, e, exact, [&](const config& c) { return c.rough == r; })).mean);
    std::printf("\n");
}

/// The per-cell oracle: for each (theta_v, roughness) of the grid, the one-lobe LTC (m_inv with
/// the middle element 1, 4 free elements, and a magnitude scale) that minimizes the mean relative
/// error over that cell's own significant configurations, against their ground truth (Nelder-
/// Mead from the shipped node, 3 restarts). Fitted to the test set: a lower bound of what any
/// one-lobe objective can reach on this grid, not a table.
evaluation oracle(const std::vector<config>& grid, const evaluation& ev) {
    evaluation e = ev;
    for (int t = 0; t < 4; ++t)
        for (int r = 0; r < 5; ++r) {
            std::vector<std::size_t> idx;
            for (std::size_t i = 0; i < grid.size(); ++i)
                if (grid[i].theta == t && grid[i].rough == r && significant(grid[i], ev.albedo[i])) idx.push_back(i);
            const auto base = ltc::ggx::fetch<double>(std::cos(thetas[t] * deg), roughnesses[r]);
            const auto coefficients = [&](const std::array<double, 5>& u) {
                ltc::ltc_coefficients<double> c = base;
                c.m_inv = glm::dmat3(1.0);
                c.m_inv[0][0] = u[0], c.m_inv[0][2] = u[1], c.m_inv[2][0] = u[2], c.m_inv[2][2] = u[3];
                c.magnitude = base.magnitude * std::exp(u[4]);
                return c;
            };
            const auto loss = [&](const std::array<double, 5>& u) {
                const auto c = coefficients(u);
                const fetch_fn f = [&](double, double) { return c; };
                double s = 0;
                for (std::size_t i : idx) s += std::abs(ltc_estimate(grid[i], f, exact) - grid[i].gt.mean) / grid[i].gt.mean;
                return idx.empty() ? 0.0 : s / double(idx.size());
            };
            std::array<double, 5> u{base.m_inv[0][0], base.m_inv[0][2], base.m_inv[2][0], base.m_inv[2][2], 0.0}, step{};
            for (int round = 0; round < 3; ++round) {
                for (int k = 0; k < 5; ++k) step[std::size_t(k)] = 0.2 * std::max(std::abs(u[std::size_t(k)]), 0.05) / (1 << round);
                u = ltc::fit::nelder_mead<5>(loss, u, step, 1e-6, 2000).x;
            }
            const auto c = coefficients(u);
            const fetch_fn f = [&](double, double) { return c; };
            for (std::size_t i : idx) e.value[exact][i] = ltc_estimate(grid[i], f, exact);
        }
    return e;
}

}  // namespace

void print_fit_objectives(const std::vector<config>& grid, const evaluation& ev, int size,
                          const std::vector<std::string>& objectives, unsigned threads) {
    std::printf("\n8. Fit objective (ltc::fit::options::goal; %dx%d tables fitted here on %u threads, exact\n"
                "   clipping): mean / p95 / max relative error over the significant configurations, theta_v = 80\n"
                "   mean, and mean by roughness 0.1 / 0.25 / 0.5 / 0.75 / 1. The oracle is no table: per (theta_v,\n"
                "   roughness), the one-lobe LTC fitted to this grid's own ground truth (a bound, not a method)\n",
                size, size, threads);
    std::printf("  %-16s %9s | %7s %7s %8s | %7s | %s\n", "objective", "fit time", "mean", "p95", "max", "80 deg",
                "by roughness: mean");
    print_row("shipped (L3)", "-", grid, ev);
    print_row("oracle (bound)", "-", grid, oracle(grid, ev));
    for (const std::string& name : objectives) {
        ltc::fit::options fo;
        fo.size = size;
        fo.threads = threads;
        fo.fit_magnitude = name.size() > 4 && name.compare(name.size() - 4, 4, "+mag") == 0;
        const std::string base = fo.fit_magnitude ? name.substr(0, name.size() - 4) : name;
        if (base == "integrals")
            fo.goal = ltc::fit::objective::integrals;
        else if (base == "combined")
            fo.goal = ltc::fit::objective::combined;
        else if (base == "l3")
            fo.goal = ltc::fit::objective::l3;
        else {
            std::printf("  %-16s (unknown objective)\n", name.c_str());
            continue;
        }
        const auto t0 = std::chrono::steady_clock::now();
        const ltc::fit::table tab = ltc::fit::fit_table<ltc::brdf::ggx>(fo);
        char time[32];
        std::snprintf(time, sizeof time, "%.2fs", seconds_since(t0));
        const std::vector<float> data = tab.packed();
        const ltc::ltc_table view(data.data(), size, size);
        const fetch_fn f = [&](double c, double r) { return view.fetch<double>(c, r); };
        evaluation e = evaluate(grid, f, false);
        e.albedo = ev.albedo;  // the shipped table's: the same significant set as section 1
        print_row(name.c_str(), time, grid, e);
    }
}

}  // namespace ggx_error_report
