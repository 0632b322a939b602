// ggx_error_report -- how far LTC shading of polygonal lights is from the real GGX integral.
//
//   ggx_error_report [--fit-sizes 8,16,32] [--objectives integrals,combined,cells,two-lobe-fit,cosine-lobe-fit] [--objective-size 64]
//                    [--target 0.002] [--threads K] [--grid on|off] [--f0 1] [--peers DIR] [--list]
//
// (--fit-sizes 0 skips section 7, --objectives none section 8; --list prints every configuration;
// about 40 s on 2 cores, plus about 10-20 s per objective of section 8, 2 s for cells, 20 s for
// two-lobe-fit, 10 s for cosine-lobe-fit.)
//
// For every configuration of a documented grid it computes the Monte Carlo ground truth of
// int_P rho_GGX(V, L) cos(theta_L) dL (ltc/reference/ground_truth.hpp: BRDF sampling + uniform spherical
// polygon sampling, balance heuristic, fixed seed, run until the standard error is below
// --target (default 0.2%) of the mean, or of 1e-3 albedo for negligible configurations, or
// 2^22 iterations), and the LTC estimate
// magnitude * I_ltc(P) of the shipped GGX table (ltc::ggx::fetch; F0 = 1, i.e. no Fresnel,
// like the ground truth; with --f0 F0 both take Schlick's factor instead, the integral of
// rho cos (F0 + (1 - F0) (1 - V.H)^5) and (F0 magnitude + (1 - F0) fresnel) I_ltc(P): --f0 0.04
// is a dielectric's specular term, largely the Fresnel part at grazing views) with each
// horizon-clipping method of ltc/shading/polygon_light.hpp:
//
//   exact        horizon_clipping::ltc_space: the paper's order, exact integral of the LTC
//   clip-first   horizon_clipping::shading_first: clip to the shading horizon, then M^-1
//   clip-once    clip to the shading horizon only, no clip in LTC space (not offered by
//                polygon_light.hpp: measured here to see what its second clip changes)
//   sphere       horizon_clipping::sphere_analytic: Hill's clipless sphere approximation
//   sphere-tab   horizon_clipping::sphere_table: the same, 32 x 32 table
//
// and prints mean, 95th percentile and max relative error |LTC - GT| / GT per method, over all
// configurations and broken down by roughness, view angle, placement and size; then the
// clipless methods against exact LTC clipping (the cost of the sphere approximation alone);
// then the error of tables fitted here at smaller sizes (ltc::fit::fit_table), with their
// fitting time and size, against the same ground truth; then tables fitted with each per-node
// objective of ltc::fit::options::goal (--objectives, --objective-size), against the same; then
// (always) the three GGX models of ltc::shade (ltc/shading/ggx_models.hpp: one_lobe,
// ltc_and_cosine, two_lobes), their specular term through ltc::shade<Model> against the same
// ground truth over the same configurations, overall and with the same breakdowns; then the
// paper's table (selfshadow/ltc_code's, read from --peers: ../shared/peers/README.md; skipped,
// saying why, where it is absent) against the shipped one, each with the sphere approximation
// (the engines' horizon) and with exact clipping.
//
// The grid (local frame N = +z, shading point at the origin, V = (sin theta_v, 0, cos theta_v)):
//   theta_v    0, 30, 60, 80 degrees (--grid off: 15, 45, 65, 75)
//   roughness  0.1, 0.25, 0.5, 0.75, 1.0 (--grid off: 0.15, 0.2, 0.35, 0.6, 0.9); alpha =
//              roughness^2 (the table's parameterization)
//   shape      rectangle (2:1), triangle (equilateral), pentagon (regular), circumradius s
//   size       s / d = 0.1, 0.5, 2 (d the distance to the light's centre: only the ratio
//              matters, the integrals see directions), the light facing the shading point
//   placement  mirror: centred on the mirror direction (-sin theta_v, 0, cos theta_v)
//              zenith: centred on N
//              side:   azimuth 90 degrees, elevation 30 degrees (off the specular lobe)
//              low:    azimuth 135 degrees, elevation 5 degrees (near the horizon)
// 720 configurations, 250 of them partly below the horizon (a vertex below it: most "low"
// lights, the large "side" ones, the large mirror ones at theta_v = 60 and 80; marked * by
// --list). Relative errors are taken over the configurations whose ground truth is
// at least 1e-3 of the BRDF's directional albedo (the rest are invisible next to any light
// that faces the lobe; they are counted and their error is reported as |LTC - GT| / albedo).
//
// Source files (tools/ggx_error_report/): grid.hpp (the configurations), ltc_estimate.hpp (the
// LTC estimate with each method), statistics.hpp (relative errors and their summaries),
// common/parallel_for.hpp (worker threads), report.hpp (the sections after the first: breakdowns.cpp,
// horizon.cpp, clipless.cpp, fit_sizes.cpp, objectives.cpp, models.cpp, paper_table.cpp), and this
// file: the command line, the ground truth, the first section and the list of every configuration.
#include "grid.hpp"
#include "ltc_estimate.hpp"
#include "common/cli.hpp"
#include "common/parallel_for.hpp"
#include "report.hpp"
#include "statistics.hpp"

#include <ltc/brdf/ggx.hpp>
#include <ltc/brdf/schlick.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

using namespace ggx_error_report;  // the pieces above

namespace {

/// "8,16,32" -> {8, 16, 32}: integers 0 .. 4096; those below 2 are left out ("0": none).
bool parse_sizes(const std::string& s, std::vector<int>& out) {
    out.clear();
    for (std::size_t b = 0; b <= s.size();) {
        const std::size_t e = std::min(s.find(',', b), s.size());
        double v = 0;
        if (!ltc_examples::parse_number(s.substr(b, e - b).c_str(), v) || v != std::floor(v) || v < 0 || v > 4096)
            return false;
        if (v >= 2) out.push_back(int(v));
        b = e + 1;
    }
    return true;
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

// The peers' folder beside the source tree (tools/CMakeLists.txt), from which section 10 reads
// the paper's table.
#ifdef LTC_PEERS_DIR
const char* const default_peers = LTC_PEERS_DIR;
#else
const char* const default_peers = "../shared/peers";
#endif

void print_help(const char* argv0) {
    std::printf(
        "usage: %s [options]\n"
        "\n"
        "LTC shading of polygonal lights (the shipped GGX table, each horizon-clipping method) against\n"
        "Monte Carlo ground truth over a grid of 720 configurations; then tables fitted here at other\n"
        "sizes and with other objectives, and the three GGX models of ltc::shade (one_lobe,\n"
        "ltc_and_cosine, two_lobes) against the same ground truth, and the paper's table (from --peers)\n"
        "against the shipped one (the file comment of tools/ggx_error_report/main.cpp).\n"
        "About 40 s on 2 cores, plus 10-20 s per objective.\n"
        "\n"
        "  --fit-sizes LIST       section 7's table sizes, comma-separated (default 8,16,32; 0: none)\n"
        "  --objectives LIST      section 8's fits (default integrals,combined,cells,two-lobe-fit,cosine-lobe-fit)\n"
        "  --objective-size N     size of section 8's tables (default 64)\n"
        "  --target T             ground truth's relative standard error, 0 .. 1 (default 0.002)\n"
        "  --threads K            worker threads (default: all hardware threads)\n"
        "  --grid on|off          the documented grid, or the one between its values (default on)\n"
        "  --f0 F0                Schlick's F0 in the truth and the LTC, 0 .. 1 (default 1: no Fresnel)\n"
        "  --peers DIR            the peers' folder, where ggx/ltc_code_ggx.txt is the paper's table (default\n"
        "                         %s; without it section 10 is skipped)\n"
        "  --list                 also print every configuration (default off)\n"
        "  --help, -h             this text\n"
        "\n"
        "Section 8's fits: l3, integrals, combined (each also with +mag: integrals+mag), cells,\n"
        "two-lobe-fit, cosine-lobe-fit; none leaves the section out.\n"
        "Progress goes to stderr: a bar on a terminal, else a line per tenth.\n",
        argv0, default_peers);
}

/// The command line (common/cli.hpp): 0 to go on, 1 after --help, 2 on an error.
int parse_args(int argc, char** argv, std::vector<int>& fit_sizes, std::vector<std::string>& objectives,
               int& objective_size, double& target, unsigned& threads, int& which_grid, std::string& peers,
               bool& list) {
    using ltc_examples::option_status;
    const auto flag = [&](const std::string& a) {
        if (a != "--list") return false;
        list = true;
        return true;
    };
    const auto option = [&](const std::string& a, const ltc_examples::option_value& v) {
        const std::string t = v.text;
        if (a == "--fit-sizes") {
            if (!parse_sizes(t, fit_sizes)) return option_status::bad;
        } else if (a == "--objectives") {
            objectives = parse_names(t);
        } else if (a == "--objective-size") {
            if (!v.integer_in(2, 4096)) return option_status::bad;
            objective_size = int(v.number);
        } else if (a == "--target") {
            if (!v.is_number || v.number < 0 || v.number > 1) return option_status::bad;
            target = v.number;
        } else if (a == "--threads") {
            if (!v.integer_in(1, 1024)) return option_status::bad;
            threads = unsigned(v.number);
        } else if (a == "--grid") {
            if (t != "on" && t != "off") return option_status::bad;
            which_grid = t == "off" ? 1 : 0;
        } else if (a == "--f0") {
            if (!v.is_number || v.number < 0 || v.number > 1) return option_status::bad;
            report_f0 = v.number;
        } else if (a == "--peers") {
            peers = t;
        } else {
            return option_status::unknown;
        }
        return option_status::taken;
    };
    return ltc_examples::parse_options(argc, argv, print_help, flag, option);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> fit_sizes = {8, 16, 32};
    std::vector<std::string> objectives = {"integrals", "combined", "cells", "two-lobe-fit", "cosine-lobe-fit"};
    int objective_size = 64;
    double target = 0.002;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    bool list = false;
    int which_grid = 0;
    std::string peers = default_peers;
    if (const int r = parse_args(argc, argv, fit_sizes, objectives, objective_size, target, threads, which_grid, peers, list);
        r != 0)
        return r == 1 ? 0 : 2;
    const auto t_start = std::chrono::steady_clock::now();

    thetas = grid_thetas[which_grid];
    roughnesses = grid_roughnesses[which_grid];
    std::vector<config> grid = make_grid();
    std::size_t straddling = 0;
    for (const auto& c : grid) straddling += c.straddles;
    if (report_f0 == 1.0)
        std::printf("LTC shading of polygonal lights vs Monte Carlo GGX ground truth\n");
    else
        std::printf("LTC shading of polygonal lights vs Monte Carlo GGX ground truth with Schlick's factor, F0 = %g\n"
                    "(rho cos F against (F0 magnitude + (1 - F0) fresnel) I_ltc; 'albedo' below is that factor)\n",
                    report_f0);
    std::printf("grid%s: theta_v {%g,%g,%g,%g} deg x roughness {%g,%g,%g,%g,%g} (alpha = roughness^2)\n"
                "      x {rectangle 2:1, triangle, pentagon} x size/distance {0.1,0.5,2}\n"
                "      x placement {mirror, zenith, side (az 90, el 30), low (az 135, el 5)}\n"
                "      = %zu configurations, %zu partly below the horizon\n\n",
                which_grid == 1 ? " (off the documented one)" : "", thetas[0], thetas[1], thetas[2], thetas[3], roughnesses[0],
                roughnesses[1], roughnesses[2], roughnesses[3], roughnesses[4], grid.size(), straddling);

    // Ground truth: relative target on the mean, and an absolute floor at `target` of the
    // significance threshold (1e-3 albedo), so that negligible configurations stop early.
    const fetch_fn shipped = [](double c, double r) { return ltc::ggx::fetch<double>(c, r); };
    ltc::ground_truth::options opt;
    opt.samples = 1u << 13;
    opt.target_relative_error = target;
    opt.max_samples = 1u << 22;
    const auto t_gt = std::chrono::steady_clock::now();
    ltc_examples::parallel_for(grid.size(), threads, [&](std::size_t i) {
        config& c = grid[i];
        const double theta = thetas[c.theta] * deg;
        const dvec3 V(std::sin(theta), 0, std::cos(theta));
        const double r = roughnesses[c.rough];
        ltc::ground_truth::options o = opt;
        o.seed = 0x5EED0000u + i;
        o.target_absolute_error = target * 1e-3 * part_scale(shipped(std::cos(theta), r));
        c.gt = report_f0 == 1.0 ? ltc::ground_truth::integrate(ltc::brdf::ggx<double>{}, V, r * r, c.vertices.data(),
                                                               c.vertices.size(), o)
                                : ltc::ground_truth::integrate(ltc::brdf::with_schlick<ltc::brdf::ggx>{report_f0}, V, r * r, c.vertices.data(),
                                                               c.vertices.size(), o);
    }, "ground truth", "configurations");
    const double gt_seconds = seconds_since(t_gt);

    const evaluation ev = evaluate(grid, shipped, true);

    std::vector<double> rse;
    std::uint64_t total_samples = 0;
    std::size_t n_sig = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        total_samples += grid[i].gt.samples;
        if (significant(grid[i], ev.albedo[i])) {
            ++n_sig;
            rse.push_back(grid[i].gt.standard_error / grid[i].gt.mean);
        }
    }
    const stats se = summarize(rse);
    std::size_t resolved = 0;
    for (std::size_t i = 0; i < grid.size(); ++i)
        if (significant(grid[i], ev.albedo[i]))
            resolved += std::abs(ev.value[exact][i] - grid[i].gt.mean) > 3 * grid[i].gt.standard_error;
    std::printf("ground truth: %.1f s on %u threads, %.2g iterations in all; relative standard error over the\n"
                "  %zu significant configurations (GT >= 1e-3 albedo): mean %.3f%%, p95 %.3f%%, max %.3f%%;\n"
                "  the exact LTC error exceeds 3 standard errors in %zu of them (the others are within the noise:\n"
                "  their error is below about 0.6%%)\n\n",
                gt_seconds, threads, double(total_samples), n_sig, 100 * se.mean, 100 * se.p95, 100 * se.max, resolved);

    const auto any = [](const config&) { return true; };
    std::printf("1. Shipped %dx%d GGX table, all %zu significant configurations: relative error |LTC - GT| / GT,\n"
                "   and the same difference relative to the directional albedo (what a light that faces the lobe\n"
                "   would show next to it)\n",
                ltc::ggx::table.width(), ltc::ggx::table.height(), n_sig);
    std::printf("  %-12s | %8s %8s %9s | %9s %9s %9s\n", "method", "mean", "p95", "max", "mean/alb", "p95/alb", "max/alb");
    for (int m = 0; m < method_count; ++m) {
        const stats s = summarize(rel_errors(grid, ev, m, any));
        std::vector<double> a;
        for (std::size_t i = 0; i < grid.size(); ++i)
            if (significant(grid[i], ev.albedo[i])) a.push_back(std::abs(ev.value[m][i] - grid[i].gt.mean) / ev.albedo[i]);
        const stats sa = summarize(a);
        std::printf("  %-12s | %7.2f%% %7.2f%% %8.2f%% | %8.3f%% %8.3f%% %8.3f%%\n", method_names[m], 100 * s.mean, 100 * s.p95,
                    100 * s.max, 100 * sa.mean, 100 * sa.p95, 100 * sa.max);
    }
    {
        std::vector<double> e;
        for (std::size_t i = 0; i < grid.size(); ++i)
            if (!significant(grid[i], ev.albedo[i])) e.push_back(std::abs(ev.value[exact][i] - grid[i].gt.mean) / ev.albedo[i]);
        const stats s = summarize(e);
        std::printf("  (the other %zu configurations, GT < 1e-3 albedo: exact |LTC - GT| / albedo <= %.2e)\n", s.count, s.max);
    }
    print_by_roughness_and_view(grid, ev);
    print_horizon(grid, ev, shipped);
    print_by_placement_and_size(grid, ev);
    print_clipless_vs_exact(grid, ev);
    print_fit_sizes(grid, ev, fit_sizes, threads);
    if (!objectives.empty()) print_fit_objectives(grid, ev, objective_size, objectives, threads);
    print_models(grid, ev);
    print_paper_table(grid, ev, shipped, peers);

    if (list) {
        std::printf("\n11. Every configuration: GT +- std error, then each method's relative error\n");
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const auto& c = grid[i];
            std::printf("  th %2.0f r %.2f %-9s s/d %.1f %-6s%s GT %.5e +- %.1e (%8llu)", thetas[c.theta], roughnesses[c.rough],
                        shape_names[c.shape], sizes[c.size], placement_names[c.placement], c.straddles ? "*" : " ", c.gt.mean,
                        c.gt.standard_error, static_cast<unsigned long long>(c.gt.samples));
            for (int m = 0; m < method_count; ++m)
                std::printf(" %+8.2f%%", c.gt.mean > 0 ? 100 * (ev.value[m][i] - c.gt.mean) / c.gt.mean : 0.0);
            std::printf("\n");
        }
    }
    std::printf("\ntotal %.1f s\n", seconds_since(t_start));
    return 0;
}
