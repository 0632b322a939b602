// textured_error_report/report.cpp -- the sections of report.hpp.
#include "report.hpp"

#include "statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace textured_error_report {

namespace {

/// f(config, texture index, texture result) for every significant configuration and texture.
template <typename F>
void for_each_case(const std::vector<config>& grid, const std::vector<config_result>& res, F&& f) {
    for (std::size_t i = 0; i < grid.size(); ++i)
        if (res[i].significant)
            for (int ti = 0; ti < texture_count; ++ti) f(grid[i], ti, res[i].tex[ti]);
}

/// The summary's columns: smooth (gradient and blobs), checker, bright detail.
constexpr int group_count = 3;
const char* const group_names[group_count] = {"smooth", "checker", "bright detail"};
int group_of(int ti) { return ti == gradient || ti == blobs ? 0 : ti == checker ? 1 : 2; }

/// A percentage with two significant digits or so (0.42%, 4.2%, 42%, 420%).
std::string pc(double x) {
    char buf[32];
    const double p = 100 * x;
    std::snprintf(buf, sizeof buf, p < 1 ? "%.2f%%" : p < 10 ? "%.1f%%" : "%.0f%%", p);
    return buf;
}

std::string label(const config& c, const inputs& in, int ti, const texture_result& t) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%-13s %-7s theta_v %2.0f dist %.1f %-9s: I_D %.3g, sigma %.3g",
                  in.textures[std::size_t(ti)].name.c_str(), lobe_names[c.lobe], views[c.view], dists[c.dist],
                  orient_names[c.orient], c.i_d, t.sigma);
    return buf;
}

/// rows = methods, columns = the summary's groups, cells mean / p95 / max.
void print_markdown(const stats (&group)[method_count][group_count]) {
    std::printf("| method |");
    for (int g = 0; g < group_count; ++g) std::printf(" %s |", group_names[g]);
    std::printf("\n|---|");
    for (int g = 0; g < group_count; ++g) std::printf("---|");
    std::printf("\n");
    for (int m = 0; m < method_count; ++m) {
        std::printf("| %s |", method_names[m]);
        for (int g = 0; g < group_count; ++g)
            std::printf(" %s / %s / %s |", pc(group[m][g].mean()).c_str(), pc(group[m][g].pct(0.95)).c_str(),
                        pc(group[m][g].max()).c_str());
        std::printf("\n");
    }
}

}  // namespace

void print_sanity_checks(const std::vector<config>& grid, const std::vector<config_result>& res, const inputs& in) {
    stats rel_se[texture_count], z, recon[texture_count], recon_signed[texture_count];
    for_each_case(grid, res, [&](const config&, int ti, const texture_result& t) {
        rel_se[ti].add(t.truth_se / t.truth);
        z.add(std::abs(sum(t.full) - t.truth) / t.truth_se);
        recon[ti].add(std::abs(t.bilinear - t.truth) / t.truth);
        recon_signed[ti].add((t.bilinear - t.truth) / t.truth);
    });
    std::printf("1. Sanity checks\n");
    std::printf("MC relative standard error (mean / max):");
    for (int ti = 0; ti < texture_count; ++ti)
        std::printf(" %s %s / %s%s", in.textures[std::size_t(ti)].name.c_str(), pc(rel_se[ti].mean()).c_str(),
                    pc(rel_se[ti].max()).c_str(), ti + 1 < texture_count ? "," : "\n");
    std::printf("Full-refinement exact_cells (64 x 64 cells: the exact texel-constant integral) against the MC,\n"
                "z = (exact - MC) / MC standard error over %zu cases: mean |z| %.2f, max |z| %.2f\n"
                "(a standard normal has mean |z| 0.80; its largest of %zu is about 3.5)\n",
                z.v.size(), z.mean(), z.max(), z.v.size());
    // The checker is shifted by 2 texels along u (setup.hpp): unshifted, u -> 1 - u (a symmetry
    // of every light and lobe here: the light's u axis is y, the lobes are symmetric in y) would
    // swap its two colours, and its exact integral would be its mean times I_D in every case.
    const image& ch = in.textures[checker];
    dvec3 mean(0.0);
    for (const dvec3& c : ch.px) mean += c / double(ch.px.size());
    double asym = 0;
    for_each_case(grid, res, [&](const config& c, int ti, const texture_result& t) {
        if (ti == checker) asym = std::max(asym, std::abs(sum(t.full) / (sum(mean) * c.i_d) - 1));
    });
    std::printf("Checker (shifted by 2 texels: unshifted, the grid's u -> 1 - u symmetry would make its exact\n"
                "integral its mean times I_D): max |exact / (mean texel x I_D) - 1| = %.2g over its cases.\n",
                asym);
    std::printf("Reconstruction: the bilinear texture's MC against the texel-constant truth (same samples),\n"
                "(bilinear - texel-constant) / texel-constant, mean |.| / max |.| / mean signed:\n");
    for (int ti = 0; ti < texture_count; ++ti)
        std::printf("  %-14s %7s / %7s / %+.2f%%\n", in.textures[std::size_t(ti)].name.c_str(), pc(recon[ti].mean()).c_str(),
                    pc(recon[ti].max()).c_str(), 100 * recon_signed[ti].mean());
}

void print_methods(const std::vector<config>& grid, const std::vector<config_result>& res, const inputs& in) {
    stats err[method_count][texture_count], bias[method_count][texture_count], shade[method_count][texture_count];
    stats group[method_count][group_count], group_exact[method_count][group_count], integrals[method_count];
    for_each_case(grid, res, [&](const config& c, int ti, const texture_result& t) {
        for (int m = 0; m < method_count; ++m) {
            err[m][ti].add(texture_error(t, m));
            bias[m][ti].add(signed_texture_error(t, m));
            shade[m][ti].add(shading_error(c, t, m));
            group[m][group_of(ti)].add(texture_error(t, m));
            group_exact[m][group_of(ti)].add(exact_error(t, m));
            integrals[m].add(double(t.integrals[m]));
        }
    });
    std::printf("\n2. Texture error |approx - MC| / MC of int L D, by method and texture\n");
    std::printf("%-19s %-14s| %-27s %8s | %s\n", "method", "texture", "texture error mean/p95/max", "bias",
                "shading error mean/p95/max");
    for (int m = 0; m < method_count; ++m) {
        for (int ti = 0; ti < texture_count; ++ti)
            std::printf("%-19s %-14s| %8s %8s %9s %+7.2f%% | %8s %8s %9s\n", ti == 0 ? method_names[m] : "",
                        in.textures[std::size_t(ti)].name.c_str(), pc(err[m][ti].mean()).c_str(),
                        pc(err[m][ti].pct(0.95)).c_str(), pc(err[m][ti].max()).c_str(), 100 * bias[m][ti].mean(),
                        pc(shade[m][ti].mean()).c_str(), pc(shade[m][ti].pct(0.95)).c_str(),
                        pc(shade[m][ti].max()).c_str());
        std::printf("%-19s polygon integrals per textured integral: mean %.1f, max %.0f\n", "", integrals[m].mean(),
                    integrals[m].max());
    }
    std::printf("(bias: mean signed texture error; shading error: |magnitude approx - MC| / MC of int L rho cos,\n"
                " the GGX fit's error included)\n");

    std::printf("\n3. Summary: texture error against the MC, mean / p95 / max (smooth = gradient and blobs)\n\n");
    print_markdown(group);
    std::printf("\nThe same against the exact texel-constant integral (full-refinement cells: no MC noise)\n\n");
    print_markdown(group_exact);
}

void print_fetch_breakdowns(const std::vector<config>& grid, const std::vector<config_result>& res, const inputs& in) {
    stats tex_err[texture_count][lobe_count], shade_err[texture_count][lobe_count], fit_err[lobe_count];
    stats by_dist[texture_count][dist_count], by_orient[texture_count][orient_count], by_view[texture_count][view_count];
    for (std::size_t i = 0; i < grid.size(); ++i)
        if (res[i].significant && !grid[i].diffuse())
            fit_err[grid[i].lobe].add(std::abs(grid[i].coeff.magnitude * grid[i].i_d - res[i].fit_truth) / res[i].fit_truth);
    for_each_case(grid, res, [&](const config& c, int ti, const texture_result& t) {
        const double e = texture_error(t, fetch);
        tex_err[ti][c.lobe].add(e);
        shade_err[ti][c.lobe].add(shading_error(c, t, fetch));
        by_dist[ti][c.dist].add(e);
        by_orient[ti][c.orient].add(e);
        by_view[ti][c.view].add(e);
    });
    std::printf("\n4. The fetch (paper) by lobe\n");
    std::printf("%-14s %-8s| %-26s | %-26s | %s\n", "texture", "lobe", "texture error mean/p95/max",
                "shading error mean/p95/max", "fit only (const) mean/max");
    for (int ti = 0; ti < texture_count; ++ti)
        for (int ri = 0; ri < lobe_count; ++ri)
            std::printf("%-14s %-8s| %8s %8s %8s | %8s %8s %8s | %8s %8s\n", in.textures[std::size_t(ti)].name.c_str(),
                        lobe_names[ri], pc(tex_err[ti][ri].mean()).c_str(), pc(tex_err[ti][ri].pct(0.95)).c_str(),
                        pc(tex_err[ti][ri].max()).c_str(), pc(shade_err[ti][ri].mean()).c_str(),
                        pc(shade_err[ti][ri].pct(0.95)).c_str(), pc(shade_err[ti][ri].max()).c_str(),
                        pc(fit_err[ri].mean()).c_str(), pc(fit_err[ri].max()).c_str());
    std::printf("\nThe fetch's texture error (mean / p95) by distance, orientation and view angle:\n");
    for (int ti = 0; ti < texture_count; ++ti) {
        std::printf("%-14s", in.textures[std::size_t(ti)].name.c_str());
        for (int di = 0; di < dist_count; ++di)
            std::printf(" d%.1f %5.2f/%5.2f%%", dists[di], 100 * by_dist[ti][di].mean(), 100 * by_dist[ti][di].pct(0.95));
        std::printf("\n%-14s", "");
        for (int oi = 0; oi < orient_count; ++oi)
            std::printf(" | %s %5.2f/%5.2f%%", orient_names[oi], 100 * by_orient[ti][oi].mean(),
                        100 * by_orient[ti][oi].pct(0.95));
        std::printf("\n%-14s", "");
        for (int vi = 0; vi < view_count; ++vi)
            std::printf(" th%2.0f %5.2f/%5.2f%%", views[vi], 100 * by_view[ti][vi].mean(), 100 * by_view[ti][vi].pct(0.95));
        std::printf("\n");
    }
}

void print_worst_cases(const std::vector<config>& grid, const std::vector<config_result>& res, const inputs& in) {
    struct worst {
        double err;
        const config* c;
        int ti;
        const texture_result* t;
    };
    const std::size_t shown[method_count] = {12, 6, 6};
    std::printf("\n5. Largest texture errors against the MC (signed; in parentheses against the exact integral)\n");
    for (int m = 0; m < method_count; ++m) {
        std::vector<worst> w;
        for_each_case(grid, res, [&](const config& c, int ti, const texture_result& t) {
            w.push_back({signed_texture_error(t, m), &c, ti, &t});
        });
        // Stable, so that ties keep the grid's order.
        std::stable_sort(w.begin(), w.end(),
                         [](const worst& a, const worst& b) { return std::abs(a.err) > std::abs(b.err); });
        std::printf("%s:\n", method_names[m]);
        for (std::size_t i = 0; i < std::min(shown[m], w.size()); ++i)
            std::printf("  %+8.2f%% (exact %+8.2f%%)  %s\n", 100 * w[i].err,
                        100 * (sum(w[i].t->approx[m]) - sum(w[i].t->full)) / sum(w[i].t->full),
                        label(*w[i].c, in, w[i].ti, *w[i].t).c_str());
    }
}

}  // namespace textured_error_report
