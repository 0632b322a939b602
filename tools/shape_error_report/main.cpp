// shape_error_report -- how far LTC shading of sphere, disk and tube lights (ltc/shading/lights/) is from the
// real GGX integral, and what each approximation on the way costs.
//
//   shape_error_report [--samples 65536] [--threads K] [--list]
//
// Direct build (as examples/CMakeLists.txt does); the run takes about 8 s on 2 cores (15 s of CPU):
//   g++ -std=gnu++17 -O2 -DNDEBUG -Wall -Wextra -Wpedantic -Werror -Iinclude -Iexamples
//       tools/shape_error_report/*.cpp -o shape_error_report -pthread   (one line)
//
// For every configuration of the grid below it computes the Monte Carlo truth of
// int_light rho_GGX(V, L) cos(theta_L) dL of the real shape (ltc/reference/shape_ground_truth.hpp:
// BRDF sampling + light sampling, balance heuristic, --samples iterations, a fixed seed per
// configuration), and the LTC estimate: the specular of shade_sphere_light / shade_disk_light /
// shade_line_light in double with F0 = 1 and radiance 1, i.e. magnitude * I_ltc (no Fresnel, as
// the truth; as ggx_error_report does for polygons), and prints per shape the mean / p95 / max of
// |LTC - truth| / truth over the significant configurations (truth >= 1e-3 of the directional
// albedo, the table's magnitude), overall and by view angle, roughness, size, placement and
// horizon. Columns:
//   sphere  exact: shade_sphere_light (the disk of tangency, integrated exactly);
//           2017: integrate_disk_2017 on that disk (Heitz and Hill 2017, EEVEE)
//   disk    exact: shade_disk_light (one-sided); 2017: integrate_disk_2017 in place of integrate_disk
//   tube    LTC vs tube: shade_line_light (2 r I_line) against MC of the real open cylinder;
//           thin line: 2 r x MC of the thin line (integrate_line, the same GGX) against MC of the
//           cylinder: the thin-line approximation alone; fit: shade_line_light against 2 r x MC of
//           the line: the LTC fit alone (the line integral is exact); ribbon: shade_tube_light (the
//           quad with the cylinder's exact silhouette, ltc/shading/tube_light.hpp) against MC of the
//           cylinder; ribbon's silhouette: MC of the real GGX over that quad (ground_truth::integrate,
//           two-sided) against MC of the cylinder: the quad's end error alone, without the fit
// Then: how often the tube's estimate exceeds the whole lobe (2 r I_line > 1: a tube wider than the
// lobe, where the thin-line limit fails); the 2017 approximation (sphere, disk) and the equal-area
// n-gon for n = 8, 16, 32, 64 (disk) against the exact shape (differences of the LTC estimates, no
// MC); the diffuse E of each shading function against its exact value (rounding only: sphere:
// Snyder's closed form of the clipped form factor; disk: a 4096-gon's polygon form factor; tube:
// 2 r times the line's closed form) and the tube's E against MC of the real cylinder's cosine (its
// thin-line error); and a sanity line: a sphere containing the point, whose LTC is the whole lobe
// (the magnitude) against the MC directional albedo.
// The MC's own relative standard error comes first; --list prints every configuration.
//
// The grid (local frame: N = +z, the shading point at the origin, V = (sin theta_v, 0, cos theta_v)):
//   theta_v    0, 30, 60, 80 deg;  roughness 0.1, 0.25, 0.5, 1 (alpha = roughness^2)
//   size       the light's angle 2, 10, 30 deg at distance 1, and "close":
//              sphere: centre at distance 1, radius sin(angle); close: the point at 1.2 radii from
//                      the centre (angular radius 56 deg)
//              disk:   centre at distance 1, normal tilted 45 deg from the point (seen as an
//                      ellipse; upwards for mirror, sideways otherwise), radius tan(angle);
//                      close: the point 0.05 radii from its plane
//              tube:   axis at distance 1, perpendicular to the direction to it, half-length
//                      tan(angle), radius 0.01 (angular width 1.1 deg); close: the 30 deg tube with
//                      radius 1/3 (the point at 3 radii from the axis)
//   placement  mirror: centred on the mirror direction (tube: axis across the plane of incidence,
//                      mirror-across, or in it, mirror-along);
//              side: azimuth 90, elevation 30 deg (tube axis horizontal);
//              straddling: azimuth 135, elevation half the light's angle (tube axis in the vertical
//                      plane), so that part of it is below the horizon
//   sphere 192, disk 192, tube 256 configurations; plus 16 spheres containing the point.
//
// Source files: grid.hpp (the configurations), evaluate.hpp (truth, LTC, exact form factors),
// statistics.hpp (errors and summaries), report.hpp / report.cpp (the sections), common/parallel_for.hpp.
#include "common/cli.hpp"
#include "common/parallel_for.hpp"
#include "evaluate.hpp"
#include "grid.hpp"
#include "report.hpp"
#include "statistics.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

using namespace shape_error_report;

namespace {

void print_help(const char* argv0) {
    std::printf(
        "usage: %s [--samples N] [--threads K] [--list]\n"
        "\n"
        "LTC shading of sphere, disk and tube lights against Monte Carlo of the real GGX integral\n"
        "(the file comment of tools/shape_error_report/main.cpp). About 8 s on 2 cores.\n"
        "\n"
        "  --samples N   Monte Carlo iterations per configuration (default 65536)\n"
        "  --threads K   worker threads (default: all hardware threads)\n"
        "  --list        also print every configuration (default off)\n"
        "  --help, -h    this text\n"
        "\n"
        "Progress goes to stderr: a bar on a terminal, else a line per tenth.\n",
        argv0);
}

}  // namespace

int main(int argc, char** argv) {
    std::uint64_t samples = 1u << 16;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    bool list = false;
    using ltc_examples::option_status;
    const auto flag = [&](const std::string& a) {
        if (a != "--list") return false;
        list = true;
        return true;
    };
    const auto option = [&](const std::string& a, const ltc_examples::option_value& v) {
        if (a == "--samples") {
            if (!v.integer_in(1, 1e12)) return option_status::bad;
            samples = std::uint64_t(v.number);
        } else if (a == "--threads") {
            if (!v.integer_in(1, 1024)) return option_status::bad;
            threads = unsigned(v.number);
        } else {
            return option_status::unknown;
        }
        return option_status::taken;
    };
    if (const int r = ltc_examples::parse_options(argc, argv, print_help, flag, option); r != 0) return r == 1 ? 0 : 2;
    const auto start = std::chrono::steady_clock::now();
    std::vector<config> grid = make_grid();
    std::size_t straddling[shape_count] = {}, count[shape_count] = {};
    for (const config& c : grid)
        if (!c.inside) ++count[c.shape], straddling[c.shape] += c.straddles;
    std::printf("LTC shading of sphere, disk and tube lights vs Monte Carlo of the real GGX (F0 = 1)\n"
                "grid: theta_v {0,30,60,80} x roughness {0.1,0.25,0.5,1} x size {2,10,30 deg, close} x placement\n"
                "      sphere %zu (%zu partly below the horizon), disk %zu (%zu), tube %zu (%zu); %llu MC iterations\n\n",
                count[sphere], straddling[sphere], count[disk], straddling[disk], count[tube], straddling[tube],
                static_cast<unsigned long long>(samples));

    ltc_examples::parallel_for(
        grid.size(), threads,
        [&](std::size_t i) {
            evaluate_ltc(grid[i]);
            evaluate_truth(grid[i], i, samples);
        },
        "evaluation", "configurations");
    const double mc_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("evaluated in %.1f s on %u threads\n", mc_seconds, threads);

    print_truth_noise(grid);
    const auto exact_error = [](const config& c) { return relative(c.ltc, c.gt.mean); };
    const auto error_2017 = [](const config& c) { return relative(c.ltc_2017, c.gt.mean); };
    print_breakdown(grid, sphere, "1. Sphere: |LTC - MC| / MC", {{"exact (shade_sphere_light)", exact_error},
                                                                  {"2017 approximation", error_2017}});
    print_breakdown(grid, disk, "2. Disk (one-sided): |LTC - MC| / MC",
                    {{"exact (shade_disk_light)", exact_error}, {"2017 approximation", error_2017}});
    const auto line = [](const config& c) { return 2 * c.radius * c.line.mean; };
    print_breakdown(grid, tube,
                    "3. Tube: LTC, ribbon vs MC of the cylinder; silhouette: MC(ribbon) vs MC(cylinder); thin line: 2 r MC(line) vs MC(cylinder); fit: LTC vs 2 r MC(line)",
                    {{"LTC vs tube", exact_error},
                     {"ribbon", [](const config& c) { return relative(c.ribbon, c.gt.mean); }},
                     {"ribbon's silhouette", [](const config& c) { return relative(c.ribbon_gt.mean, c.gt.mean); }},
                     {"thin line", [&](const config& c) { return relative(line(c), c.gt.mean); }},
                     {"fit (LTC vs line)", [&](const config& c) { return relative(c.ltc, line(c)); }}});
    print_tube_overshoot(grid);
    print_approximations(grid);
    print_diffuse_and_sanity(grid);
    if (list) print_list(grid);
    std::printf("total %.1f s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return 0;
}
