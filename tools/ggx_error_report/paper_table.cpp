// ggx_error_report/paper_table.cpp -- section 10 of the report: what an engine gains by swapping
// the paper's GGX table (selfshadow/ltc_code's fit/results/ltc.js, the one three.js ships) for the
// shipped one-lobe table, both shaded as the engines shade (one lobe times the magnitude, the
// sphere approximation at the horizon) and with exact clipping, against the same ground truth;
// and the paper's matrices with the shipped magnitude, the part an engine that scales the lobe
// by a magnitude of its own (EEVEE since 4.2: its split-sum term) gains.
// The paper's table is not part of the project: it is read from the peers' folder
// (../shared/peers/README.md), and the section is skipped, saying why, where it is absent.
#include "grid.hpp"
#include "ltc_estimate.hpp"
#include "report.hpp"
#include "statistics.hpp"

#include <ltc/tables/ltc_table.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace ggx_error_report {

namespace {

/// A square table in ltc_table's layout, owning its floats.
struct owned_table {
    std::vector<float> data;
    int size = 0;
};

/// The peers' text (ggx/ltc_code_ggx.txt): rows "t a m00 m02 m20 m22 magnitude" and '#' comments,
/// the normalized M^-1 printed row-major [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] at node t along
/// u = sqrt(1 - cos theta_v) and node a along roughness, the layout of ltc_table. The bottom-left
/// m20 (row 2, column 0) is GLM's m_inv[0][2]; the text has no Fresnel column, so fresnel is 0.
/// False, with why, where the file is absent or not every node of a square grid once.
bool read_paper_table(const std::string& path, owned_table& out, std::string& why) {
    std::ifstream text(path);
    if (!text) {
        why = "no " + path;
        return false;
    }
    struct row {
        int t, a;
        float m00, m02, m20, m22, magnitude;
    };
    std::vector<row> rows;
    int n = 0, line_number = 0;
    for (std::string line; std::getline(text, line);) {
        ++line_number;
        if (line.empty() || line[0] == '#') continue;
        std::istringstream in(line);
        row r{-1, -1, 0, 0, 0, 0, 0};
        in >> r.t >> r.a >> r.m00 >> r.m02 >> r.m20 >> r.m22 >> r.magnitude;
        if (!in || r.t < 0 || r.a < 0 || r.t > 4095 || r.a > 4095) {
            why = path + ", line " + std::to_string(line_number) + ": not \"t a m00 m02 m20 m22 magnitude\"";
            return false;
        }
        n = std::max(n, std::max(r.t, r.a) + 1);
        rows.push_back(r);
    }
    out.size = n;
    out.data.assign(std::size_t(n) * std::size_t(n) * ltc::channel::count, 0.0f);
    std::vector<int> seen(std::size_t(n) * std::size_t(n), 0);
    for (const row& r : rows) {
        const std::size_t node = std::size_t(r.a) * std::size_t(n) + std::size_t(r.t);
        seen[node] += 1;
        float* c = &out.data[node * ltc::channel::count];
        c[ltc::channel::m_inv_00] = r.m00;
        c[ltc::channel::m_inv_02] = r.m20;
        c[ltc::channel::m_inv_20] = r.m02;
        c[ltc::channel::m_inv_22] = r.m22;
        c[ltc::channel::magnitude] = r.magnitude;
    }
    if (n < 2 || std::count(seen.begin(), seen.end(), 1) != std::ptrdiff_t(seen.size())) {
        why = path + ": not every node of a " + std::to_string(n) + " x " + std::to_string(n) + " grid once";
        return false;
    }
    return true;
}

}  // namespace

void print_paper_table(const std::vector<config>& grid, const evaluation& ev, const fetch_fn& shipped,
                       const std::string& peers) {
    if (report_f0 != 1.0) {
        std::printf("\n10. The paper's GGX table against the shipped one: skipped, the paper's text has no Fresnel column\n"
                    "    (the section runs at --f0 1 only)\n");
        return;
    }
    owned_table paper;
    std::string why;
    if (!read_paper_table(peers + "/ggx/ltc_code_ggx.txt", paper, why)) {
        std::printf("\n10. The paper's GGX table against the shipped one: skipped, %s\n", why.c_str());
        return;
    }
    const ltc::ltc_table view(paper.data.data(), paper.size, paper.size);
    evaluation pe = evaluate(grid, [&](double c, double r) { return view.fetch<double>(c, r); }, true);
    pe.albedo = ev.albedo;  // the shipped table's: section 1's significant set for both tables
    // The paper's M^-1 scaled by the shipped magnitude: the swap's gain with the magnitude held fixed.
    evaluation pm = evaluate(
        grid,
        [&](double c, double r) {
            ltc::ltc_coefficients<double> l = view.fetch<double>(c, r);
            const ltc::ltc_coefficients<double> own = shipped(c, r);
            l.magnitude = own.magnitude;
            l.fresnel = own.fresnel;
            return l;
        },
        true);
    pm.albedo = ev.albedo;

    const auto any = [](const config&) { return true; };
    // The criterion: the light gives more than 5% of the directional albedo.
    const auto bright = [&](const config& c) { return c.gt.mean > 0.05 * albedo_at(c, shipped); };
    const std::size_t n_all = summarize(rel_errors(grid, ev, exact, any)).count;
    const std::size_t n_bright = summarize(rel_errors(grid, ev, exact, bright)).count;
    std::printf("\n10. What an engine gains by swapping the paper's GGX table (%dx%d, selfshadow/ltc_code's\n"
                "   fit/results/ltc.js, the one three.js ships; read from --peers) for the shipped one-lobe table\n"
                "   (ltc::ggx::table, %dx%d): magnitude * I_ltc of each table's lobe, F0 = 1, with the engines'\n"
                "   horizon handling (\"sphere\": the horizon-clipped form factor of the sphere that has the vector\n"
                "   form factor of M^-1 P, Hill and Heitz 2016, here in closed form; three.js fits it, the paper's\n"
                "   demo reads it from a table) and with exact clipping in LTC space (\"exact\"). Relative error\n"
                "   |LTC - GT| / GT against the same ground truth over the same %zu significant configurations as\n"
                "   section 1, and over the %zu of them where the light gives more than 5%% of the directional\n"
                "   albedo (GT > 0.05 albedo, the shipped table's magnitude); paper/shipped: the ratio of the means.\n"
                "   \"paper M^-1\": the paper's matrices times the shipped table's magnitude, what an engine that\n"
                "   scales the normalized lobe by a magnitude of its own (EEVEE since 4.2, by its split-sum term)\n"
                "   gains, the magnitude held fixed; M^-1/shipped: the ratio of its mean to the shipped table's\n",
                paper.size, paper.size, ltc::ggx::table.width(), ltc::ggx::table.height(), n_all, n_bright);
    char all[32];
    std::snprintf(all, sizeof all, "all (%zu)", n_all);
    std::printf("  %-8s %-13s | %-25s | GT > 5%% albedo (%zu)\n", "horizon", "table", all, n_bright);
    std::printf("  %-22s | %7s %7s %8s  | %7s %7s %8s\n", "", "mean", "p95", "max", "mean", "p95", "max");
    for (int m : {int(sphere), int(exact)}) {
        const stats s[2][2] = {{summarize(rel_errors(grid, pe, m, any)), summarize(rel_errors(grid, pe, m, bright))},
                               {summarize(rel_errors(grid, ev, m, any)), summarize(rel_errors(grid, ev, m, bright))}};
        for (int t = 0; t < 2; ++t)
            std::printf("  %-8s %-13s | %6.2f%% %6.2f%% %7.2f%%  | %6.2f%% %6.2f%% %7.2f%%\n", method_names[m],
                        t == 0 ? "paper" : "shipped", 100 * s[t][0].mean, 100 * s[t][0].p95, 100 * s[t][0].max,
                        100 * s[t][1].mean, 100 * s[t][1].p95, 100 * s[t][1].max);
        std::printf("  %-8s %-13s | %7.2f %17s | %7.2f\n", method_names[m], "paper/shipped", s[0][0].mean / s[1][0].mean, "",
                    s[0][1].mean / s[1][1].mean);
        const stats sm[2] = {summarize(rel_errors(grid, pm, m, any)), summarize(rel_errors(grid, pm, m, bright))};
        std::printf("  %-8s %-13s | %6.2f%% %6.2f%% %7.2f%%  | %6.2f%% %6.2f%% %7.2f%%\n", method_names[m], "paper M^-1",
                    100 * sm[0].mean, 100 * sm[0].p95, 100 * sm[0].max, 100 * sm[1].mean, 100 * sm[1].p95, 100 * sm[1].max);
        std::printf("  %-8s %-13s | %7.2f %17s | %7.2f\n", method_names[m], "M^-1/shipped", sm[0].mean / s[1][0].mean, "",
                    sm[1].mean / s[1][1].mean);
    }
}

}  // namespace ggx_error_report
