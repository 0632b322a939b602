// textured_error_report -- how close each textured-light method of ltc/shading/textured_light.hpp
// comes to the integral of its texture, against Monte Carlo ground truth.
//
//   textured_error_report [--threads K]     (about 25-35 s on 2 busy cores; the output does not
//                                            depend on K: every configuration has its own seeds)
//
// Methods (double precision):
//   fetch (paper)     textured_method::fetch: I_D I_L, one prefiltered fetch (sections 5.2-5.4)
//   quick_cells, means  integrate_quick_cells(..., use_fetch = false): quick_cells' leaves, each
//                     its texels' mean, without the fetch in wide leaves (why that rule is there)
//   quick_cells       textured_method::quick_cells
//   exact_cells (64)  textured_method::exact_cells, budget.max_cells = 64
//
// Truth: the texture every method approximates is the texel-constant one (radiance
// ltc::nearest_image_lookup; the exact cells converge to its integral). Per configuration and
// texture, the Monte Carlo of int_quad L D of ltc/reference/textured_ground_truth.hpp with the
// LTC lobe D itself (so the fit of the BRDF plays no part): 2^15 iterations, lobe sampling +
// area sampling (half uniform, half proportional to the RGB sum of each texel's brightest 3 x 3
// neighbour), balance heuristic, a fixed seed per configuration and texture; the radiance is
// the RGB sum (the errors sum RGB before the ratio), so the estimate carries the sum's own
// standard error.
//
// Configurations (all combinations; the shading point at the origin, N = +z, V = (sin theta_v,
// 0, cos theta_v)), 180 of them, 177 with I_D >= 1e-4 (the rest are skipped), x 4 textures:
//   lobe          the clamped cosine (diffuse, M = I) and GGX at roughness 0.1, 0.25, 0.5, 1
//                 (alpha = roughness^2; the shipped table's M^-1)
//   view angle    theta_v = 0, 30, 60, 80 degrees
//   light         a 1 x 1 square whose centre is at distance 0.5, 1.5 or 4 in the direction of
//                 elevation 45 deg on the mirror side (azimuth 180 deg), facing the shading
//                 point, tilted by 60 deg about its horizontal axis, or vertical (normal
//                 horizontal, pointing to the shading point's side); its u axis is +y
//   texture       64 x 64 texels: "gradient" (u, v, 1 - u v); "blobs" (0.05 plus Gaussian blobs
//                 (1, 0.3, 0.1) at uv (0.3, 0.3) sigma 0.12, (0.1, 0.8, 0.3) at (0.7, 0.6) sigma
//                 0.15, (0.2, 0.3, 1.2) at (0.45, 0.85) sigma 0.08); "checker" (4 x 4-texel
//                 cells, 0.05 and 1, shifted by 2 texels along u); "bright detail" (0.02 background, a 3 x 3-texel patch of
//                 (100, 80, 60) at uv ~ (0.7, 0.35): 17% of the energy in 0.2% of the area).
//                 "Smooth" in the summary: gradient and blobs together.
//
// Sections:
//   1. sanity checks: the MC's relative standard error; the full-refinement exact_cells (budget
//      64 x 64 cells: the exact texel-constant integral) against the MC as z = (exact - MC) /
//      standard error (mean |z| and max |z|; a correct MC gives about 0.8 and a max near 3.5);
//      how far the checker's exact integral lies from its mean times I_D (the checker is
//      shifted by 2 texels: every light and lobe here is symmetric under u -> 1 - u, which
//      would swap an unshifted checker's two colours and make the mean exact); and the MC of
//      the bilinear texture (bilinear_image_lookup, same seed and density: common random
//      numbers) against the texel-constant truth, what the choice of reconstruction changes.
//   2. per method and texture: texture error |sum_rgb(approx) - MC| / MC, mean / p95 / max and
//      bias (mean signed error); shading error |magnitude sum_rgb(approx) - MC'| / MC' with MC'
//      the MC of int L rho cos (GGX BRDF lobe, same texture; for the diffuse lobe MC' = MC and
//      magnitude = 1), which adds the GGX fit's error; polygon integrals per textured integral.
//   3. the headline: a Markdown table, rows = methods, columns = smooth, checker, bright detail,
//      texture error mean / p95 / max against the MC; then the same against the full-refinement
//      exact integral (no MC noise: the approximation's own error).
//   4. the fetch by lobe (texture error, shading error, and "fit only": |magnitude I_D - MC| / MC
//      of int rho cos with the constant texture 1, the untextured LTC error), then by distance,
//      orientation and view angle.
//   5. the largest texture errors of each method (against the MC and the exact integral).
//   6. the prefilter's timing for a 1024 x 1024 image (ltc::light_texture<float>).
//
// Source files (tools/textured_error_report/): setup.hpp (textures, MC densities, the grid,
// seeds), evaluate.hpp (one configuration: methods and MC), statistics.hpp (the errors and their
// summaries), report.hpp / report.cpp (sections 1-5), and this file; worker threads from
// examples/common/parallel_for.hpp.
#include "evaluate.hpp"
#include "common/cli.hpp"
#include "common/parallel_for.hpp"
#include "report.hpp"
#include "setup.hpp"

#include <ltc/shading/light_texture.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

using namespace textured_error_report;  // the pieces above

namespace {

void print_help(const char* argv0) {
    std::printf(
        "usage: %s [--threads K]\n"
        "\n"
        "Each textured-light method of ltc/shading/textured_light.hpp against Monte Carlo of its\n"
        "texture's integral (the file comment of tools/textured_error_report/main.cpp). About\n"
        "25-35 s on 2 cores; the output does not depend on the thread count.\n"
        "\n"
        "  --threads K   worker threads (default: all hardware threads)\n"
        "  --help, -h    this text\n"
        "\n"
        "Progress goes to stderr: a bar on a terminal, else a line per tenth.\n",
        argv0);
}

}  // namespace

int main(int argc, char** argv) {
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    using ltc_examples::option_status;
    const auto no_flags = [](const std::string&) { return false; };
    const auto option = [&](const std::string& a, const ltc_examples::option_value& v) {
        if (a != "--threads") return option_status::unknown;
        if (!v.integer_in(1, 1024)) return option_status::bad;
        threads = unsigned(v.number);
        return option_status::taken;
    };
    if (const int r = ltc_examples::parse_options(argc, argv, print_help, no_flags, option); r != 0)
        return r == 1 ? 0 : 2;
    const auto t_start = std::chrono::steady_clock::now();
    const auto seconds_since = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };

    inputs in;
    for (int t = 0; t < texture_count; ++t) in.textures.push_back(make_texture(t));
    for (const image& im : in.textures) {
        in.prefiltered.emplace_back(im.w, im.h, im.px.data());
        in.densities.push_back(luminance_density(im));
    }
    const std::vector<config> grid = make_grid();
    std::vector<config_result> res(grid.size());
    ltc_examples::parallel_for(
        grid.size(), threads, [&](std::size_t i) { res[i] = evaluate(grid[i], i, in); }, "measurements",
        "configurations");
    const double eval_seconds = seconds_since(t_start);

    const std::size_t significant = std::size_t(std::count_if(res.begin(), res.end(), [](const config_result& r) {
        return r.significant;
    }));
    std::printf("Textured quad lights: fetch (paper), quick_cells with means, quick_cells, exact_cells (64)\n"
                "against Monte Carlo of the texel-constant texture\n");
    std::printf("%zu configurations (%zu skipped: I_D < 1e-4) x %d textures = %zu cases; MC 2^15 iterations each\n\n",
                grid.size(), grid.size() - significant, int(texture_count), significant * texture_count);
    print_sanity_checks(grid, res, in);
    print_methods(grid, res, in);
    print_fetch_breakdowns(grid, res, in);
    print_worst_cases(grid, res, in);

    std::printf("\n6. Prefilter timing, 1024 x 1024 RGB (%u hardware threads):\n", std::thread::hardware_concurrency());
    std::vector<glm::vec3> big(std::size_t(1024) * 1024);
    for (std::size_t i = 0; i < big.size(); ++i)
        big[i] = glm::vec3(float(i % 1024) / 1024, float((i / 1024) % 7) / 7, float((i * 2654435761u) % 1000) / 1000);
    for (double margin : {ltc::light_texture<float>::default_margin, 0.25}) {
        const auto t0 = std::chrono::steady_clock::now();
        const ltc::light_texture<float> tex(1024, 1024, big.data(), margin);
        const double s = seconds_since(t0);
        std::size_t texels = 0;
        for (int k = 0; k < tex.level_count(); ++k) texels += tex.get_level(k).texels.size();
        std::printf("  margin %.3f: %d levels, %.1f MB, %.2f s\n", margin, tex.level_count(), double(texels) * 12.0 / 1e6, s);
    }
    std::printf("\nMeasurements %.1f s on %u threads; total %.1f s\n", eval_seconds, threads, seconds_since(t_start));
    return 0;
}
