// sheen_error_report -- how far LTC shading of polygonal lights with the Charlie sheen table
// (ltc::charlie::fetch, ltc/tables/charlie.hpp: the model ltc::sheen::charlie of ltc::shade) is
// from the real integral of KHR_materials_sheen's Charlie BRDF (ltc/brdf/charlie.hpp), and what
// the fit's objective and the table's size change.
//
//   sheen_error_report [--fits l3,integrals,combined,combined@32] [--target 0.002]
//                      [--threads K] [--list]
//
// (--fits none leaves section 4 out; about a minute on 2 cores, plus 10-40 s per fit: docs/results/
// sheen_error.md is the default run, tools/results.sh.)
//
// The grid is ggx_error_report's (tools/ggx_error_report/grid.hpp: theta_v 0, 30, 60, 80 deg x
// roughness 0.1, 0.25, 0.5, 0.75, 1 (alpha = roughness^2, the sheen roughness of the spec) x
// rectangle, triangle, pentagon x size/distance 0.1, 0.5, 2 x placement mirror, zenith, side,
// low: 720 lights facing the shading point). For each it computes the Monte Carlo ground truth
// of int_P rho_charlie(V, L) cos(theta_L) dL (ltc::ground_truth::integrate: the model's uniform
// hemisphere sampling + uniform spherical polygon sampling, balance heuristic, fixed seed per
// configuration, until the standard error is below --target of the mean, or of 5% of the albedo
// for the configurations that do not count, or 2^22 iterations), and the LTC estimate
// magnitude * I_ltc(P) (exact clipping in LTC space, horizon_clipping::ltc_space, the default of
// ltc::shade; no sheen colour, like the truth). Relative errors |LTC - GT| / GT are taken over the
// significant configurations: those whose truth is at least 5% of the directional albedo at their
// (theta_v, roughness) (computed by quadrature here, independently of any table), i.e. lights
// that give a visible part of the sheen, where that albedo is at least 1e-3 (below it the sheen
// reflects less than a thousandth of the light: the smoothest sheens seen from near the normal;
// the line "albedo < 1e-3 too" counts those as well). Sections: 1. the MC's own noise; 2. the shipped table,
// overall and by roughness, view angle, placement and size; 3. the table's magnitude against the
// albedo; 4. tables fitted here with each objective of ltc::fit::options::goal (l3, integrals,
// combined; NAME@N for an N x N table, 64 by default), their fit time and errors on the same set.
#include "common/cli.hpp"
#include "common/error_summary.hpp"
#include "common/parallel_for.hpp"
#include "common/progress.hpp"
#include "ggx_error_report/grid.hpp"

#include <ltc/brdf/charlie.hpp>
#include <ltc/fitting/fit.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/charlie_fetch.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>
#include <vector>

using namespace ggx_error_report;  // the grid
using ltc_examples::stats;
using ltc_examples::summarize;

namespace {

using fetch_fn = std::function<ltc::ltc_coefficients<double>(double, double)>;
constexpr double significance = 0.05;  // of the albedo: the lights that count
constexpr double visible_albedo = 1e-3;  // (theta_v, roughness) with a smaller albedo show no sheen

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

dvec3 view_of(const config& c) {
    const double theta = thetas[c.theta] * deg;
    return dvec3(std::sin(theta), 0, std::cos(theta));
}

/// magnitude * I_ltc(P), exact clipping in LTC space; the lights are front-facing: one-sided.
double ltc_estimate(const config& c, const fetch_fn& fetch) {
    const dvec3 N(0, 0, 1), V = view_of(c), P(0);
    const auto frame = ltc::make_shading_frame(N, V);
    const auto lobe = fetch(frame.cos_theta_v, roughnesses[c.rough]);
    const double I = ltc::integrate_polygon_light(frame, lobe.m_inv, P, c.vertices.data(), c.vertices.size(),
                                                  ltc::horizon_clipping::ltc_space)
                         .ltc;
    return lobe.magnitude * std::max(0.0, I);
}

struct ground {
    std::vector<config> grid;
    std::vector<double> albedo;  // per configuration: the directional albedo by quadrature
    bool faint = false;  // also count the (theta_v, roughness) of an albedo below visible_albedo
    bool significant(std::size_t i) const {
        return grid[i].gt.mean >= significance * albedo[i] && (faint || albedo[i] >= visible_albedo);
    }
};

std::vector<double> estimates(const ground& g, const fetch_fn& fetch) {
    std::vector<double> v(g.grid.size());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = ltc_estimate(g.grid[i], fetch);
    return v;
}

stats errors(const ground& g, const std::vector<double>& v, const std::function<bool(const config&)>& keep) {
    std::vector<double> e;
    for (std::size_t i = 0; i < g.grid.size(); ++i)
        if (g.significant(i) && keep(g.grid[i])) e.push_back(std::abs(v[i] - g.grid[i].gt.mean) / g.grid[i].gt.mean);
    return summarize(e);
}

void print_stats_row(const char* label, const stats& s) {
    std::printf("  %-24s %4zu | %7.2f%% %7.2f%% %8.2f%%\n", label, s.count, 100 * s.mean, 100 * s.p95, 100 * s.max);
}

void print_breakdowns(const ground& g, const std::vector<double>& v) {
    char label[64];
    std::printf("  %-24s %4s | %8s %8s %9s\n", "", "n", "mean", "p95", "max");
    print_stats_row("all", errors(g, v, [](const config&) { return true; }));
    for (int r = 0; r < 5; ++r) {
        std::snprintf(label, sizeof label, "roughness %g", roughnesses[r]);
        print_stats_row(label, errors(g, v, [r](const config& c) { return c.rough == r; }));
    }
    for (int t = 0; t < 4; ++t) {
        std::snprintf(label, sizeof label, "theta_v %g deg", thetas[t]);
        print_stats_row(label, errors(g, v, [t](const config& c) { return c.theta == t; }));
    }
    for (int p = 0; p < 4; ++p) {
        std::snprintf(label, sizeof label, "placement %s", placement_names[p]);
        print_stats_row(label, errors(g, v, [p](const config& c) { return c.placement == p; }));
    }
    for (int s = 0; s < 3; ++s) {
        std::snprintf(label, sizeof label, "size/distance %g", sizes[s]);
        print_stats_row(label, errors(g, v, [s](const config& c) { return c.size == s; }));
    }
    print_stats_row("partly below the horizon", errors(g, v, [](const config& c) { return c.straddles; }));
    ground with_faint = g;
    with_faint.faint = true;
    print_stats_row("all, albedo < 1e-3 too", errors(with_faint, v, [](const config&) { return true; }));
}

std::vector<std::string> parse_names(const std::string& s) {
    std::vector<std::string> r;
    std::size_t b = 0;
    while (b < s.size()) {
        const std::size_t e = std::min(s.find(',', b), s.size());
        if (e > b && s.compare(b, e - b, "none") != 0) r.push_back(s.substr(b, e - b));
        b = e + 1;
    }
    return r;
}

void print_help(const char* argv0) {
    std::printf(
        "usage: %s [options]\n"
        "\n"
        "LTC shading of polygonal lights with the Charlie sheen table (ltc::charlie::fetch, the model\n"
        "ltc::sheen::charlie) against Monte Carlo ground truth of the Charlie BRDF over ggx_error_report's\n"
        "grid of 720 lights, counting those that give at least 5 percent of the albedo; then tables fitted\n"
        "here with each objective (the file comment of tools/sheen_error_report/main.cpp).\n"
        "About a minute on 2 cores, plus 10-40 s per fit.\n"
        "\n"
        "  --fits LIST     section 4's tables: l3, integrals or combined, each optionally @N for an N x N\n"
        "                  table (default l3,integrals,combined,combined@32; none: no section 4)\n"
        "  --target T      ground truth's relative standard error, 0 .. 1 (default 0.002)\n"
        "  --threads K     worker threads (default: all hardware threads)\n"
        "  --list          also print every significant configuration (default off)\n"
        "  --help, -h      this text\n"
        "Progress goes to stderr: a bar on a terminal, else a line per tenth.\n",
        argv0);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> fits = {"l3", "integrals", "combined", "combined@32"};
    double target = 0.002;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    bool list = false;
    {
        using ltc_examples::option_status;
        const auto flag = [&](const std::string& a) {
            if (a != "--list") return false;
            list = true;
            return true;
        };
        const auto option = [&](const std::string& a, const ltc_examples::option_value& v) {
            if (a == "--fits") {
                fits = parse_names(v.text);
            } else if (a == "--target") {
                if (!v.is_number || v.number < 0 || v.number > 1) return option_status::bad;
                target = v.number;
            } else if (a == "--threads") {
                if (!v.integer_in(1, 1024)) return option_status::bad;
                threads = unsigned(v.number);
            } else {
                return option_status::unknown;
            }
            return option_status::taken;
        };
        if (const int r = ltc_examples::parse_options(argc, argv, print_help, flag, option); r != 0) return r == 1 ? 0 : 2;
    }
    const auto t_start = std::chrono::steady_clock::now();

    ground g;
    g.grid = make_grid();
    std::printf("LTC shading of polygonal lights vs Monte Carlo ground truth of the Charlie sheen (KHR_materials_sheen)\n"
                "grid: theta_v {%g,%g,%g,%g} deg x sheen roughness {%g,%g,%g,%g,%g} (alpha = roughness^2)\n"
                "      x {rectangle 2:1, triangle, pentagon} x size/distance {0.1,0.5,2}\n"
                "      x placement {mirror, zenith, side (az 90, el 30), low (az 135, el 5)} = %zu configurations\n\n",
                thetas[0], thetas[1], thetas[2], thetas[3], roughnesses[0], roughnesses[1], roughnesses[2], roughnesses[3],
                roughnesses[4], g.grid.size());

    // The directional albedo per (theta_v, roughness), by the midpoint rule on 256 x 256 samples
    // of the model's sampler (the fitter's moments, at 16 times its samples).
    double cell_albedo[4][5];
    for (int t = 0; t < 4; ++t)
        for (int r = 0; r < 5; ++r) {
            const double theta = thetas[t] * deg;
            cell_albedo[t][r] = ltc::fit::compute_moments<ltc::brdf::charlie>(dvec3(std::sin(theta), 0, std::cos(theta)),
                                                                               roughnesses[r] * roughnesses[r], 256)
                                    .magnitude;
        }
    g.albedo.resize(g.grid.size());
    for (std::size_t i = 0; i < g.grid.size(); ++i) g.albedo[i] = cell_albedo[g.grid[i].theta][g.grid[i].rough];

    ltc::ground_truth::options opt;
    opt.samples = 1u << 13;
    opt.target_relative_error = target;
    opt.max_samples = 1u << 22;
    const auto t_gt = std::chrono::steady_clock::now();
    ltc_examples::parallel_for(g.grid.size(), threads, [&](std::size_t i) {
        config& c = g.grid[i];
        const double r = roughnesses[c.rough];
        ltc::ground_truth::options o = opt;
        o.seed = 0x5EED0000u + i;
        o.target_absolute_error = target * significance * g.albedo[i];
        c.gt = ltc::ground_truth::integrate(ltc::brdf::charlie<double>{}, view_of(c), r * r, c.vertices.data(),
                                            c.vertices.size(), o);
    }, "ground truth", "configurations");
    const double gt_seconds = seconds_since(t_gt);

    std::vector<double> rse;
    std::uint64_t total_samples = 0;
    for (std::size_t i = 0; i < g.grid.size(); ++i) {
        total_samples += g.grid[i].gt.samples;
        if (g.significant(i)) rse.push_back(g.grid[i].gt.standard_error / g.grid[i].gt.mean);
    }
    const stats se = summarize(rse);
    std::printf("1. Ground truth: %.1f s on %u threads, %.2g iterations in all; %zu significant configurations\n"
                "   (GT >= 5%% of the albedo >= 1e-3); their relative standard error: mean %.3f%%, p95 %.3f%%, max %.3f%%\n\n",
                gt_seconds, threads, double(total_samples), se.count, 100 * se.mean, 100 * se.p95, 100 * se.max);

    const fetch_fn shipped = [](double c, double r) { return ltc::charlie::fetch<double>(c, r); };
    const std::vector<double> v = estimates(g, shipped);
    std::printf("2. Shipped %dx%d Charlie table (ltc/tables/charlie.hpp), relative error |LTC - GT| / GT over the\n"
                "   significant configurations\n",
                ltc::charlie::table.width(), ltc::charlie::table.height());
    print_breakdowns(g, v);

    std::printf("\n3. The table's magnitude against the directional albedo (256 x 256 quadrature) at the grid's\n"
                "   (theta_v, roughness): relative difference\n  %-10s", "roughness");
    for (int t = 0; t < 4; ++t) std::printf("   theta_v %2g", thetas[t]);
    std::printf("\n");
    for (int r = 0; r < 5; ++r) {
        std::printf("  %-10g", roughnesses[r]);
        for (int t = 0; t < 4; ++t) {
            const double m = ltc::charlie::fetch<double>(std::cos(thetas[t] * deg), roughnesses[r]).magnitude;
            const double a = cell_albedo[t][r];
            std::printf("  %+10.2e%s", a > 0 ? m / a - 1 : 0.0, a < 1e-3 ? "*" : " ");
        }
        std::printf("\n");
    }
    std::printf("  (* albedo below 1e-3: no visible sheen; the table interpolates a function that varies fast there)\n");

    if (!fits.empty()) {
        std::printf("\n4. Tables fitted here (ltc::fit::fit_table<ltc::brdf::charlie>, objective of options::goal,\n"
                    "   magnitude = the directional albedo) on %u threads, over the same significant configurations:\n"
                    "   mean / p95 / max relative error, and mean by roughness %g / %g / %g / %g / %g\n",
                    threads, roughnesses[0], roughnesses[1], roughnesses[2], roughnesses[3], roughnesses[4]);
        std::printf("  %-16s %9s | %7s %7s %8s | %-34s | %s\n", "objective", "fit time", "mean", "p95", "max", "by roughness: mean",
                    "mean, albedo < 1e-3 too");
        for (const std::string& name : fits) {
            const std::size_t at = name.find('@');
            const std::string base = name.substr(0, at);
            ltc::fit::options fo;
            fo.threads = threads;
            if (at != std::string::npos) fo.size = std::max(2, std::atoi(name.c_str() + at + 1));
            if (base == "l3") fo.goal = ltc::fit::objective::l3;
            else if (base == "integrals") fo.goal = ltc::fit::objective::integrals;
            else if (base == "combined") fo.goal = ltc::fit::objective::combined;
            else {
                std::printf("  %-16s (unknown objective)\n", name.c_str());
                continue;
            }
            ltc_examples::progress shown("fit " + name, "nodes");
            const auto t0 = std::chrono::steady_clock::now();
            const ltc::fit::table tab =
                ltc::fit::fit_table<ltc::brdf::charlie>(fo, [&](std::size_t d, std::size_t t) { shown.update(d, t); });
            const double secs = seconds_since(t0);
            const std::vector<float> data = tab.packed();
            const ltc::ltc_table view(data.data(), fo.size, fo.size);
            const std::vector<double> e = estimates(g, [&](double c, double r) { return view.fetch<double>(c, r); });
            const stats s = errors(g, e, [](const config&) { return true; });
            char label[64];
            std::snprintf(label, sizeof label, "%s, %dx%d", base.c_str(), fo.size, fo.size);
            std::printf("  %-16s %8.2fs | %6.2f%% %6.2f%% %7.2f%% |", label, secs, 100 * s.mean, 100 * s.p95, 100 * s.max);
            for (int r = 0; r < 5; ++r)
                std::printf(" %5.1f%%", 100 * errors(g, e, [r](const config& c) { return c.rough == r; }).mean);
            ground with_faint = g;
            with_faint.faint = true;
            std::printf(" | %8.2f%%\n", 100 * errors(with_faint, e, [](const config&) { return true; }).mean);
        }
    }

    if (list) {
        std::printf("\n5. Every significant configuration: GT +- standard error (iterations), albedo, LTC's relative error\n");
        for (std::size_t i = 0; i < g.grid.size(); ++i) {
            if (!g.significant(i)) continue;
            const auto& c = g.grid[i];
            std::printf("  th %2.0f r %.2f %-9s s/d %.1f %-6s%s GT %.5e +- %.1e (%8llu) albedo %.4f  %+8.2f%%\n",
                        thetas[c.theta], roughnesses[c.rough], shape_names[c.shape], sizes[c.size],
                        placement_names[c.placement], c.straddles ? "*" : " ", c.gt.mean, c.gt.standard_error,
                        static_cast<unsigned long long>(c.gt.samples), g.albedo[i], 100 * (v[i] - c.gt.mean) / c.gt.mean);
        }
    }
    std::printf("\ntotal %.1f s\n", seconds_since(t_start));
    return 0;
}
