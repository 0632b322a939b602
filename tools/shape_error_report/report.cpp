// shape_error_report/report.cpp -- the report's sections (report.hpp; main.cpp's file comment).
#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace shape_error_report {

namespace {

void print_row(const std::vector<config>& grid, int shape, const std::vector<column>& cols, const std::string& label,
               const std::function<bool(const config&)>& keep) {
    const std::size_t n = errors(grid, shape, cols[0], keep).size();
    if (n == 0) return;
    std::printf("  %-15s %4zu", label.c_str(), n);
    for (const column& col : cols) {
        const stats s = summarize(errors(grid, shape, col, keep));
        std::printf(" | %6.2f%% %6.2f%% %7.2f%%", 100 * s.mean, 100 * s.p95, 100 * s.max);
    }
    std::printf("\n");
}

double rse(const ltc::ground_truth::estimate& e) { return e.mean > 0 ? e.standard_error / e.mean : 0.0; }

void print_stats_line(const char* label, const std::vector<double>& e, double scale = 100, const char* unit = "%") {
    const stats s = summarize(e);
    std::printf("  %-44s n %3zu  mean %.3g%s  p95 %.3g%s  max %.3g%s\n", label, s.count, scale * s.mean, unit,
                scale * s.p95, unit, scale * s.max, unit);
}

}  // namespace

void print_truth_noise(const std::vector<config>& grid) {
    std::printf("Monte Carlo truth: relative standard error over the significant configurations\n");
    for (int shape = 0; shape < shape_count; ++shape) {
        std::vector<double> e, line, cosine;
        std::size_t total = 0, resolved = 0;
        for (const config& c : grid) {
            if (c.shape != shape || c.inside) continue;
            ++total;
            if (!significant(c)) continue;
            e.push_back(rse(c.gt));
            resolved += std::abs(c.ltc - c.gt.mean) > 3 * c.gt.standard_error;
            if (shape == tube) line.push_back(rse(c.line)), cosine.push_back(rse(c.tube_cosine));
        }
        const std::string label = std::string(shape_names[shape]) + " (" + std::to_string(e.size()) + " of " +
                                  std::to_string(total) + ", LTC error > 3 sigma in " + std::to_string(resolved) + ")";
        print_stats_line(label.c_str(), e);
        if (shape == tube) {
            print_stats_line("  its thin line (GGX)", line);
            print_stats_line("  the cylinder's cosine (diffuse)", cosine);
        }
    }
    std::printf("\n");
}

void print_breakdown(const std::vector<config>& grid, int shape, const char* title, const std::vector<column>& cols) {
    std::printf("%s\n  %-15s %4s", title, "configurations", "n");
    for (const column& col : cols) std::printf(" | %-24s", col.name);
    std::printf("\n  %-20s", "");
    for (std::size_t k = 0; k < cols.size(); ++k) std::printf(" | %7s %7s %8s", "mean", "p95", "max");
    std::printf("\n");
    print_row(grid, shape, cols, "all", [](const config&) { return true; });
    print_row(grid, shape, cols, "all but close", [](const config& c) { return c.size != 3; });
    for (int t = 0; t < 4; ++t)
        print_row(grid, shape, cols, "theta_v " + std::to_string(int(thetas[t])), [t](const config& c) { return c.theta == t; });
    for (int r = 0; r < 4; ++r) {
        char label[32];
        std::snprintf(label, sizeof label, "roughness %.2g", roughnesses[r]);
        print_row(grid, shape, cols, label, [r](const config& c) { return c.rough == r; });
    }
    for (int s = 0; s < size_count; ++s)
        print_row(grid, shape, cols, std::string("size ") + size_names[s], [s](const config& c) { return c.size == s; });
    for (int p = 0; p < placement_counts[shape]; ++p)
        print_row(grid, shape, cols, placement_names[shape][p], [p](const config& c) { return c.placement == p; });
    print_row(grid, shape, cols, "above horizon", [](const config& c) { return !c.straddles; });
    print_row(grid, shape, cols, "partly below", [](const config& c) { return c.straddles; });
    std::printf("\n");
}

void print_approximations(const std::vector<config>& grid) {
    std::printf("Approximations against the exact shape, both through the same LTC (no Monte Carlo):\n"
                "  |approximation - exact| / exact over the significant configurations, entirely above the horizon\n"
                "  or partly below it: the 2017 approximation (sphere, disk) and the equal-area n-gon\n"
                "  (integrate_disk_polygon, disk)\n");
    const auto line = [&](int shape, const char* name, const std::function<double(const config&)>& value) {
        for (int part = 0; part < 2; ++part) {
            std::vector<double> e;
            for (const config& c : grid)
                if (c.shape == shape && significant(c) && c.straddles == (part == 1)) e.push_back(relative(value(c), c.ltc));
            const std::string label = std::string(shape_names[shape]) + ", " + name + (part ? ", partly below" : ", above");
            print_stats_line(label.c_str(), e);
        }
    };
    line(sphere, "2017", [](const config& c) { return c.ltc_2017; });
    line(disk, "2017", [](const config& c) { return c.ltc_2017; });
    for (int k = 0; k < 4; ++k) {
        const std::string name = "n = " + std::to_string(polygon_sizes[k]);
        line(disk, name.c_str(), [k](const config& c) { return c.polygon[k]; });
    }
    std::printf("\n");
}

void print_tube_overshoot(const std::vector<config>& grid) {
    std::size_t over = 0, total = 0;
    double worst = 0, ribbon = 0;
    for (const config& c : grid)
        if (c.shape == tube) {
            ++total;
            over += c.ltc > c.albedo;
            worst = std::max(worst, c.ltc / c.albedo);
            ribbon = std::max(ribbon, c.ribbon / c.albedo);
        }
    std::printf("Tube: 2 r I_line > 1 (the LTC estimate above the whole lobe, magnitude) in %zu of %zu configurations,\n"
                "  up to %.2f x the magnitude: a tube wider (2 r / distance) than the lobe; the ribbon (I <= 1)\n"
                "  reaches at most %.3f x the magnitude\n\n",
                over, total, worst, ribbon);
}

void print_diffuse_and_sanity(const std::vector<config>& grid) {
    std::printf("Diffuse: E of shade_*_light (double) against its exact value (sphere: Snyder's closed form;\n"
                "  disk: the 4096-gon's polygon form factor; tube: 2 r times the line's closed form), relative,\n"
                "  over every configuration with E > 0; and the tube's thin-line error for E: 2 r I_line,cos\n"
                "  against Monte Carlo of the real cylinder's cosine, and the ribbon's E (shade_tube_light) against it\n");
    for (int shape = 0; shape < shape_count; ++shape) {
        std::vector<double> e, thin[size_count], ribbon[size_count];
        for (const config& c : grid)
            if (c.shape == shape && !c.inside && c.diffuse_exact > 0) {
                e.push_back(relative(c.diffuse, c.diffuse_exact));
                if (shape == tube && c.tube_cosine.mean > 0) {
                    thin[c.size].push_back(relative(c.diffuse, c.tube_cosine.mean));
                    ribbon[c.size].push_back(relative(c.ribbon_diffuse, c.tube_cosine.mean));
                }
            }
        print_stats_line(shape_names[shape], e);
        if (shape == tube)
            for (int s = 0; s < size_count; ++s) {
                const std::string label = std::string("  tube vs cylinder MC, size ") + size_names[s];
                print_stats_line(label.c_str(), thin[s]);
            }
        if (shape == tube)
            for (int s = 0; s < size_count; ++s) {
                const std::string label = std::string("  ribbon vs cylinder MC, size ") + size_names[s];
                print_stats_line(label.c_str(), ribbon[s]);
            }
    }
    std::vector<double> spec, diff, noise;
    for (const config& c : grid)
        if (c.inside) {
            spec.push_back(relative(c.ltc, c.gt.mean));
            diff.push_back(std::abs(c.diffuse - 1));
            noise.push_back(rse(c.gt));
        }
    std::printf("\nSanity: a sphere containing the point (16 views x roughnesses): the whole lobe\n");
    print_stats_line("specular: magnitude vs MC albedo, relative", spec);
    print_stats_line("  (MC relative standard error)", noise);
    print_stats_line("diffuse: |E - 1|", diff, 1, "");
    std::printf("\n");
}

void print_list(const std::vector<config>& grid) {
    std::printf("Every configuration: truth +- standard error, LTC's relative error (sphere, disk: the 2017's; tube:\n"
                "  2 r x MC of the line +- standard error, and the LTC's error against it; shade_tube_light's and\n"
                "  MC(ribbon)'s error against MC(cylinder), and MC(ribbon)'s relative standard error); * partly below the\n"
                "  horizon, - not significant\n");
    for (const config& c : grid) {
        std::printf("  %-6s th %2.0f r %.2f %-6s %-13s%s%s GT %.4e +- %.1e LTC %+8.2f%%", shape_names[c.shape],
                    thetas[c.theta], roughnesses[c.rough], c.inside ? "-" : size_names[c.size],
                    c.inside ? "inside" : placement_names[c.shape][c.placement], c.straddles ? "*" : " ",
                    significant(c) || c.inside ? " " : "-", c.gt.mean, c.gt.standard_error,
                    c.gt.mean > 0 ? 100 * (c.ltc - c.gt.mean) / c.gt.mean : 0.0);
        if (c.shape == disk || (c.shape == sphere && !c.inside))
            std::printf(" 2017 %+8.2f%%", c.gt.mean > 0 ? 100 * (c.ltc_2017 - c.gt.mean) / c.gt.mean : 0.0);
        if (c.shape == tube)
            std::printf(" line %.4e +- %.1e fit %+.2f%%", 2 * c.radius * c.line.mean, 2 * c.radius * c.line.standard_error,
                        c.line.mean > 0 ? 100 * (c.ltc / (2 * c.radius * c.line.mean) - 1) : 0.0);
        if (c.shape == tube)
            std::printf(" ribbon %+.2f%% silhouette %+.2f%% +- %.2f%%", c.gt.mean > 0 ? 100 * (c.ribbon / c.gt.mean - 1) : 0.0,
                        c.gt.mean > 0 ? 100 * (c.ribbon_gt.mean / c.gt.mean - 1) : 0.0,
                        c.ribbon_gt.mean > 0 ? 100 * c.ribbon_gt.standard_error / c.ribbon_gt.mean : 0.0);
        std::printf("\n");
    }
}

}  // namespace shape_error_report
