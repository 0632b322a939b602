// ggx_error_report/models.cpp -- section 9 of the report: the three GGX models of ltc::shade
// (ltc/shading/ggx_models.hpp: one_lobe, ltc_and_cosine, the default, and two_lobes), each the
// specular term of ltc::shade<Model> (double, default options: horizon clipping in LTC space, the
// exact edge terms) for a one-sided light of radiance 1 with F0 = --f0, against the same ground
// truth over the same significant configurations as section 1 (the significance threshold and
// the "/alb" columns use the shipped one-lobe table's albedo, so that every model is measured on
// the same set), overall and by roughness, view angle, horizon and placement and size.
#include "grid.hpp"
#include "ltc_estimate.hpp"
#include "report.hpp"
#include "statistics.hpp"

#include <ltc/shading/ggx_cosine_lobe_fetch.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/ggx_models.hpp>
#include <ltc/shading/ggx_two_lobe_fetch.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/shade.hpp>
#include <ltc/shading/surface.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <vector>

namespace ggx_error_report {

namespace {

/// The model's specular term per configuration, in value[exact] (the others are left empty).
template <typename Model>
evaluation shade_model(const std::vector<config>& grid, const evaluation& ev) {
    evaluation e;
    e.value[exact].resize(grid.size());
    e.albedo = ev.albedo;  // the shipped table's: the same significant set as section 1
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const config& c = grid[i];
        const double theta = thetas[c.theta] * deg;
        ltc::surface<double> s;
        s.position = dvec3(0);
        s.normal = dvec3(0, 0, 1);
        s.view = dvec3(std::sin(theta), 0, std::cos(theta));
        s.roughness = roughnesses[c.rough];
        s.f0 = dvec3(report_f0);
        s.albedo = dvec3(0);
        // grid.hpp's lights turn clockwise as seen from the shading point: their front faces it.
        const auto light = ltc::polygon_light<double>::one_sided(c.vertices.data(), c.vertices.size(),
                                                                 ltc::winding::clockwise_front, dvec3(1));
        e.value[exact][i] = ltc::shade<Model>(s, light).specular.x;
    }
    return e;
}

struct model_row {
    const char* name;
    int size;
    evaluation e;
};

using keep_fn = std::function<bool(const config&)>;

void print_cells(const std::vector<config>& grid, const std::vector<model_row>& rows, const keep_fn& keep) {
    for (const model_row& m : rows) {
        const stats s = summarize(rel_errors(grid, m.e, exact, keep));
        std::printf(" | %5.1f%% %6.1f%% %7.1f%%", 100 * s.mean, 100 * s.p95, 100 * s.max);
    }
    std::printf("\n");
}

}  // namespace

void print_models(const std::vector<config>& grid, const evaluation& ev) {
    std::vector<model_row> rows;
    rows.push_back({"one_lobe", ltc::ggx::table.width(), shade_model<ltc::ggx::one_lobe>(grid, ev)});
    rows.push_back({"ltc_and_cosine", ltc::ggx_cosine_lobe::size, shade_model<ltc::ggx::ltc_and_cosine>(grid, ev)});
    rows.push_back({"two_lobes", ltc::ggx_two_lobe::size, shade_model<ltc::ggx::two_lobes>(grid, ev)});

    const auto any = [](const config&) { return true; };
    std::size_t n_sig = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) n_sig += significant(grid[i], ev.albedo[i]);
    char f0[48];
    if (report_f0 == 1.0)
        std::snprintf(f0, sizeof f0, "F0 = 1 (no Fresnel)");
    else
        std::snprintf(f0, sizeof f0, "F0 = %g", report_f0);
    std::printf("\n9. The GGX models of ltc::shade (ltc/shading/ggx_models.hpp; ltc_and_cosine is the default):\n"
                "   the specular term of ltc::shade<Model> in double, default options (horizon clipping in LTC\n"
                "   space, as \"exact\" above), %s, against the same ground truth over the same\n"
                "   %zu significant configurations: relative error |LTC - GT| / GT, and the same difference\n"
                "   relative to the albedo of section 1 (the one-lobe table's, for every model)\n",
                f0, n_sig);
    std::printf("  %-15s %5s | %8s %8s %9s | %9s %9s %9s\n", "model", "table", "mean", "p95", "max", "mean/alb", "p95/alb",
                "max/alb");
    for (const model_row& m : rows) {
        const stats s = summarize(rel_errors(grid, m.e, exact, any));
        std::vector<double> a;
        for (std::size_t i = 0; i < grid.size(); ++i)
            if (significant(grid[i], ev.albedo[i]))
                a.push_back(std::abs(m.e.value[exact][i] - grid[i].gt.mean) / ev.albedo[i]);
        const stats sa = summarize(a);
        char table[16];
        std::snprintf(table, sizeof table, "%dx%d", m.size, m.size);
        std::printf("  %-15s %5s | %7.2f%% %7.2f%% %8.2f%% | %8.3f%% %8.3f%% %8.3f%%\n", m.name, table, 100 * s.mean,
                    100 * s.p95, 100 * s.max, 100 * sa.mean, 100 * sa.p95, 100 * sa.max);
    }
    {  // one_lobe through ltc::shade is section 1's exact estimate: how far apart they are
        double d = 0;
        for (std::size_t i = 0; i < grid.size(); ++i)
            if (significant(grid[i], ev.albedo[i]))
                d = std::max(d, std::abs(rows[0].e.value[exact][i] - ev.value[exact][i]) / grid[i].gt.mean);
        std::printf("  (one_lobe against section 1's exact estimate: max |difference| / GT = %.1e)\n", d);
    }

    std::printf("\n   By roughness (alpha = roughness^2): mean / p95 / max relative error\n");
    std::printf("  %-15s", "roughness");
    for (const model_row& m : rows) std::printf(" | %-22s", m.name);
    std::printf("\n");
    for (int r = 0; r < 5; ++r) {
        std::printf("  %-15.2f", roughnesses[r]);
        print_cells(grid, rows, [&](const config& c) { return c.rough == r; });
    }
    std::printf("\n   By view angle\n");
    for (int t = 0; t < 4; ++t) {
        std::printf("  theta_v %-7.0f", thetas[t]);
        print_cells(grid, rows, [&](const config& c) { return c.theta == t; });
    }
    std::printf("\n   Lights entirely above vs partly below the horizon\n");
    std::printf("  %-15s", "above");
    print_cells(grid, rows, [](const config& c) { return !c.straddles; });
    std::printf("  %-15s", "straddling");
    print_cells(grid, rows, [](const config& c) { return c.straddles; });
    std::printf("\n   By placement and size\n");
    for (int pl = 0; pl < 4; ++pl)
        for (int sz = 0; sz < 3; ++sz) {
            char label[64];
            std::snprintf(label, sizeof label, "%-6s s/d=%.1f", placement_names[pl], sizes[sz]);
            std::printf("  %-15s", label);
            print_cells(grid, rows, [&](const config& c) { return c.placement == pl && c.size == sz; });
        }
}

}  // namespace ggx_error_report
