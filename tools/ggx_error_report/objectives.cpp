// ggx_error_report/objectives.cpp -- section 8 of the report: tables fitted here with each per-node
// objective of ltc::fit::options::goal (the paper's L3 distance, the integral objective of
// ltc/fitting/integral_objective.hpp, their sum; each optionally with a fitted magnitude scale),
// their fitting time, against the same ground truth and over the same significant
// configurations as section 1 (the significance threshold uses the shipped table's albedo, so
// that a fitted magnitude does not change the set). Also two-lobe rows: the shipped
// two-lobe table (ltc/shading/ggx_two_lobe_fetch.hpp), its fit timed here ("two-lobe-fit"), and
// "cells": per (theta_v, roughness) cell, the one- and two-lobe fits at the cell's exact view
// and roughness (no table: what any table resolution or spacing could reach at best). And the
// table of an LTC and the clamped cosine, the default shading's
// (ltc/shading/ggx_cosine_lobe_fetch.hpp), its fit timed here ("cosine-lobe-fit"), and its per-cell fits ("cells, LTC+cosine").
#include "common/progress.hpp"
#include "grid.hpp"
#include "ltc_estimate.hpp"
#include "report.hpp"
#include "statistics.hpp"

#include <ltc/brdf/ggx.hpp>
#include <ltc/fitting/fit.hpp>
#include <ltc/fitting/fit_two_lobes.hpp>
#include <ltc/shading/ggx_cosine_lobe_fetch.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/ggx_two_lobe_fetch.hpp>
#include <ltc/tables/ltc_table.hpp>

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
                c.fresnel = base.fresnel * std::exp(u[4]);
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

/// Per (theta_v, roughness) cell of the grid, fits at the cell's exact view and roughness (no
/// table, no interpolation): the one-lobe L3 fit (marched from normal incidence as fit_table does)
/// and the two-lobe fit started from it. lobes = 1 or 2; with `model` ltc_and_cosine, lobe 1 is the
/// cosine and the LTC starts from the one-lobe fit (start_with_cosine).
evaluation cell_fits(const std::vector<config>& grid, const evaluation& ev, int lobes, double& seconds,
                     bool refit_first = true, ltc::fit::two_lobe_model model = ltc::fit::two_lobe_model::two_ltcs) {
    evaluation e = ev;
    const auto t0 = std::chrono::steady_clock::now();
    ltc::fit::options fo;
    for (int r = 0; r < 5; ++r) {
        const double alpha = std::max(roughnesses[r] * roughnesses[r], fo.alpha_min);
        ltc::fit::ltc_parameters start;
        start.m11 = start.m22 = alpha;
        for (int t = 0; t < 4; ++t) {
            const double c = std::max(std::cos(thetas[t] * deg), fo.cos_theta_min);
            const double x = std::sqrt(1 - c);
            const int steps = std::max(1, int(std::ceil(x * 48)));
            ltc::fit::node_result node = ltc::fit::fit_node<ltc::brdf::ggx>(1.0, alpha, start, fo);
            for (int k = 1; k <= steps && x > 0; ++k) {  // from normal incidence to theta_v
                const double xk = x * k / steps;
                node = ltc::fit::fit_node<ltc::brdf::ggx>(std::max(1 - xk * xk, fo.cos_theta_min), alpha, node.parameters, fo);
            }
            std::array<ltc::ltc_coefficients<double>, 2> lobe;
            lobe[0].m_inv = node.m_inv;
            lobe[0].magnitude = node.magnitude;
            lobe[0].fresnel = node.fresnel;
            lobe[1].magnitude = lobe[1].fresnel = 0;
            if (lobes == 2) {
                const ltc::fit::two_lobe_start st = model == ltc::fit::two_lobe_model::ltc_and_cosine
                                                        ? ltc::fit::start_with_cosine(node.parameters)
                                                        : ltc::fit::start_from_one_lobe(node.parameters);
                const auto two = ltc::fit::fit_two_lobes<ltc::brdf::ggx>(c, alpha, st, fo, refit_first);
                for (int l = 0; l < 2; ++l) lobe[std::size_t(l)].m_inv = two.m_inv[std::size_t(l)];
                lobe[0].magnitude = two.magnitude * (1 - two.share);
                lobe[1].magnitude = two.magnitude * two.share;
                lobe[0].fresnel = two.fresnel * (1 - two.fresnel_share);
                lobe[1].fresnel = two.fresnel * two.fresnel_share;
            }
            for (std::size_t i = 0; i < grid.size(); ++i) {
                if (grid[i].theta != t || grid[i].rough != r) continue;
                double v = 0;
                for (int l = 0; l < lobes; ++l) {
                    const auto cf = lobe[std::size_t(l)];
                    const fetch_fn f = [&](double, double) { return cf; };
                    v += ltc_estimate(grid[i], f, exact);
                }
                e.value[exact][i] = v;
            }
        }
    }
    seconds = seconds_since(t0);
    return e;
}

/// Both lobes' estimates summed (ltc/shading/ggx_two_lobe_fetch.hpp's layout: each lobe an
/// ordinary table whose magnitude carries its share; with `premultiplied`, lobe 2's m_inv
/// premultiplied, as in ltc/shading/ggx_cosine_lobe_fetch.hpp), over the same significant set.
evaluation evaluate_two_lobes(const std::vector<config>& grid, const evaluation& ev, const ltc::ltc_table& lobe1,
                              const ltc::ltc_table& lobe2, bool premultiplied = false) {
    const fetch_fn f1 = [&](double c, double r) { return lobe1.fetch<double>(c, r); };
    const fetch_fn f2 = [&](double c, double r) {
        const auto l = lobe2.fetch<double>(c, r);
        return premultiplied ? ltc::ggx_cosine_lobe::unpremultiplied(l) : l;
    };
    evaluation e = evaluate(grid, f1, false);
    const evaluation e2 = evaluate(grid, f2, false);
    for (std::size_t i = 0; i < grid.size(); ++i) e.value[exact][i] += e2.value[exact][i];
    e.albedo = ev.albedo;
    return e;
}

}  // namespace

void print_fit_objectives(const std::vector<config>& grid, const evaluation& ev, int size,
                          const std::vector<std::string>& objectives, unsigned threads) {
    std::printf("\n8. Fit objective (ltc::fit::options::goal; %dx%d tables fitted here on %u threads, exact\n"
                "   clipping): mean / p95 / max relative error over the significant configurations, theta_v = %g\n"
                "   mean, and mean by roughness %g / %g / %g / %g / %g. The oracle is no table: per (theta_v,\n"
                "   roughness), the one-lobe LTC fitted to this grid's own ground truth (a bound, not a method)\n",
                size, size, threads, thetas[3], roughnesses[0], roughnesses[1], roughnesses[2], roughnesses[3], roughnesses[4]);
    char grazing[32];
    std::snprintf(grazing, sizeof grazing, "%g deg", thetas[3]);
    std::printf("  %-16s %9s | %7s %7s %8s | %7s | %s\n", "objective", "fit time", "mean", "p95", "max", grazing,
                "by roughness: mean");
    print_row("shipped (L3)", "-", grid, ev);
    print_row("oracle (bound)", "-", grid, oracle(grid, ev));
    print_row("two-lobe table", "-", grid,
              evaluate_two_lobes(grid, ev, ltc::ggx_two_lobe::lobe_table(0), ltc::ggx_two_lobe::lobe_table(1)));
    print_row("LTC+cosine table", "-", grid,
              evaluate_two_lobes(grid, ev, ltc::ggx_cosine_lobe::lobe_table(0), ltc::ggx_cosine_lobe::lobe_table(1), true));
    for (const std::string& name : objectives) {
        if (name == "cells") {
            double secs = 0;
            char time[32];
            const evaluation e1 = cell_fits(grid, ev, 1, secs);
            std::snprintf(time, sizeof time, "%.2fs", secs);
            print_row("cells, one lobe", time, grid, e1);
            const evaluation e2 = cell_fits(grid, ev, 2, secs);
            std::snprintf(time, sizeof time, "%.2fs", secs);
            print_row("cells, two lobes", time, grid, e2);
            const evaluation e3 = cell_fits(grid, ev, 2, secs, false);
            std::snprintf(time, sizeof time, "%.2fs", secs);
            print_row("cells, lobe 1 L3", time, grid, e3);
            const evaluation e4 = cell_fits(grid, ev, 2, secs, true, ltc::fit::two_lobe_model::ltc_and_cosine);
            std::snprintf(time, sizeof time, "%.2fs", secs);
            print_row("cells, LTC+cos", time, grid, e4);
            continue;
        }
        if (name == "two-lobe-fit" || name == "cosine-lobe-fit") {  // a shipped two-lobe table's fit, timed here
            const bool cosine = name == "cosine-lobe-fit";
            ltc::fit::options fo;
            fo.size = ltc::fit::two_lobe_default_size;
            fo.threads = threads;
            const auto t0 = std::chrono::steady_clock::now();
            const std::vector<float> data =
                ltc::fit::fit_two_lobe_table<ltc::brdf::ggx>(fo, cosine ? ltc::fit::two_lobe_model::ltc_and_cosine
                                                                        : ltc::fit::two_lobe_model::two_ltcs)
                    .packed();
            char time[32];
            std::snprintf(time, sizeof time, "%.2fs", seconds_since(t0));
            const ltc::ltc_table lobe1(data.data(), fo.size, fo.size), lobe2(data.data() + data.size() / 2, fo.size, fo.size);
            print_row(cosine ? "LTC+cosine, 32x32" : "two lobes, 32x32", time, grid,
                      evaluate_two_lobes(grid, ev, lobe1, lobe2, cosine));
            continue;
        }
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
        ltc_examples::progress shown("fit " + name, "nodes");
        const auto t0 = std::chrono::steady_clock::now();
        const ltc::fit::table tab =
            ltc::fit::fit_table<ltc::brdf::ggx>(fo, [&](std::size_t d, std::size_t t) { shown.update(d, t); });
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
