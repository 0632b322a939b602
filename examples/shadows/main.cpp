// shadows -- a small CPU renderer with real shadows, traced by Embree 3: LTC shading with
// ratio-estimator shadows (ltc::shade_shadowed) against plain Monte Carlo.
//
//   shadows [--width W] [--height H] [--spp LIST] [--adaptive-spp LIST] [--area-spp LIST]
//           [--mis-spp LIST] [--denoised-spp LIST] [--denoised-mis-spp LIST]
//           [--denoise-radius R|auto] [--filter-radius penumbra|fixed] [--ltc-correction on|off]
//           [--pixel-points screen|random] [--reference-spp N] [--threads K] [--out DIR] [--seed S] [--exposure E]
//           [--lobes 1|2|cosine] [--help]
//
// The scene (z up; scene.hpp), every surface triangles of one Embree scene (tracer.hpp): a floor
// of unit tiles, GGX dielectrics (F0 = 0.04, Lambertian albedo 0.5) of roughness 0.15, 0.3 and
// 0.6 in diagonals, and one column of gold tiles (the same roughnesses, no diffuse); one
// one-sided 2.6 x 1.0 quad light of constant radiance 3 units up, behind the occluders, facing
// the camera and the floor; two rough grey occluders (roughness 0.5, F0 0.04, albedo 0.45): a
// unit box standing on the floor (a contact shadow, hard at its base and softening away from it)
// and a panel with a square hole, slanted 30 degrees sideways, 0.5 to 1.7 units up (narrow and
// wide penumbrae, a soft spot of light through the hole). A pinhole camera, one ray per pixel
// centre (camera.hpp), sees the floor, the occluders and the light (drawn as its radiance where
// its front is seen, black from behind).
//
// Methods, each shading every floor and occluder pixel with the light's direct light:
//   (a)  ratio_ltc   LTC + ratio-estimator shadows (Heitz, Hill and McGuire 2018): the analytic
//                    unshadowed LTC (GGX table, Schlick's Fresnel) times, per term, the ratio of
//                    the shadowed to the unshadowed Monte Carlo estimates over the same K samples,
//                    one shadow ray each, split between the LTC restricted to the polygon and the
//                    light's area in proportion to the specular and diffuse analytic shares and
//                    combined by the balance heuristic (the library's default; shade_ratio.hpp);
//   (a+) ratio_ltc_adaptive  (a) with an early stop, an experiment of this example: K0 = min(K, 4)
//                    samples first; where both terms' ratios are exactly 0 or 1 (all samples
//                    agreed: umbra, or fully lit), that result; else (a) again with K samples and
//                    another rotation, and the two ratios averaged with weights K0 and K;
//   (b)  ratio_area  the same ratio estimator, its K samples uniform over the light's area;
//   (c)  mis         plain Monte Carlo with MIS: per iteration one BRDF sample (GGX visible
//                    normals, or the cosine lobe) and one light-area sample, balance heuristic,
//                    of GGX with Schlick's Fresnel plus Lambert: the BRDF the LTC approximates
//                    (shade_mis.hpp);
//   (d)  ratio_ltc_denoised  (a), then its two Monte Carlo estimates per term (ltc::ratio_estimates)
//                    filtered over neighbouring pixels, each on its own, and the ratio of the
//                    filtered values applied to the pixel's analytic terms (ltc::ratio_shading):
//                    Heitz, Hill and McGuire's denoising, which blurs the shadows, not the shading;
//                    by default (--ltc-correction on) the specular term instead takes the
//                    filtered estimates of the shadowed integrals relative to their analytic
//                    values, per part of Hill's Fresnel split (ltc::corrected_specular), which
//                    corrects the LTC's fitting error as well; by default (--filter-radius
//                    penumbra) each pixel's radius is at most R and about half the width of the
//                    penumbra there, as the blocker distances of its and its neighbours'
//                    occluded shadow rays give it (percentage-closer soft shadows' estimate:
//                    denoise.hpp's penumbra_radii), so that hard shadow edges are not blurred;
//   (e)  mis_denoised  (c), then its radiance filtered by the same filter with the radius R
//                    everywhere ((c) records no blockers): the same denoiser on plain Monte
//                    Carlo, so that (d) is compared with a denoised baseline too.
//                    The filter (denoise.hpp): cross-bilateral, separable, Gaussian of sigma r / 2
//                    pixels, r = R or (d)'s own radius (--denoise-radius R; by default R =
//                    4 (K / 4)^(-1/6) rounded, K the samples or iterations: denoise.hpp's
//                    auto_radius), on the centre pixel's surface only
//                    (kind, normal, plane), timed with the shading; (e)'s taps of the centre's
//                    material, (d)'s diffuse sums shared across materials and its specular sums
//                    between tiles of one roughness (their f carries no albedo or Fresnel term).
//                    (d) draws (a)'s random numbers, (e) (c)'s (with screen-ordered points, the
//                    default, (c) keeps its random ones and (e) takes screen-ordered ones: below).
// Sample points (screen_order.hpp): by default the per-pixel points of every method but (c) (the
// lattice rotation of (a), (a+)'s first call, (b) and (d), with shadow_sampling::stratified_rotation;
// each iteration's light point, lobe choice and lobe point of (e)) come from a screen-space
// ordering of scrambled Sobol points, so that neighbouring pixels' points are stratified together;
// each pixel's point stays uniform, so that every Monte Carlo sum keeps its expectation, and the
// errors that the filters of (d) and (e) average over neighbours partly cancel. (c), unfiltered,
// keeps random numbers (the ordering would only cost it time), and so does the reference.
// --pixel-points random: independent random numbers per pixel everywhere (the example before the
// ordering: its output byte for byte).
// With --lobes 2 or --lobes cosine, (a), (a+), (b) and (d) take their analytic part from the opt-in
// two-lobe GGX table (ltc::ggx::two_lobes) or the table of an LTC and the cosine
// (ltc::ggx::ltc_and_cosine, ltc::shade's default model), and the
// samples of (a), (a+) and (d) follow that table's first, or only, LTC; (c), (e) and the reference do not change.
// "spp" is K for (a), (a+), (b) and (d) and the iterations of (c) and (e): per pixel, (a), (b) and
// (d) cast up to K shadow rays, (a+) K0, or K0 + K where the first K0 disagree, (c) and (e) up to K
// shadow and K BRDF rays (the tables' rays/px; (d) with --filter-radius penumbra traces its shadow
// rays as closest-hit queries, for the blockers' distances; timed). The reference is (c) at
// --reference-spp iterations with its own seeds: direct lighting only, since the light is the only
// emitter and the floor's inter-reflection is not what the methods compute. It is the direct light
// of the real BRDF, so the errors of (a), (a+), (b) and (d) with --ltc-correction off include the
// LTC fit's as well as their shadows' ((d) corrects it by default).
// (a+)'s average rather than the K-sample result alone: it uses all K0 + K rays paid for, and it
// scales the early stop's bias by K / (K0 + K). Measured in a default run with random rotations
// (the K-sample result alone, in brackets): mean |e| over the floor 11.5% (14.3%) at K = 4,
// 8.7% (8.8%) at K = 16;
// shift from (a), the early stop's bias, 5.7% (11.3%) and 7.2% (9.1%) RMS. That bias: where the
// light is partly hidden, all K0 samples can still agree (for independent samples with
// probability about v^K0 + (1 - v)^K0, v the visible fraction; the lattice lowers it, not to 0),
// and the pixel then keeps 0 or 1: near-lit pixels turn lit and near-umbra ones dark, penumbrae
// harden and small or thin occlusions (a sliver of the lobe hidden) vanish. It is not noise, and
// more samples K do not remove it: the average keeps a share K / (K0 + K) of it, which grows to
// all of it as K grows; only a larger K0 shrinks it.
//
// Written into --out (default: the current directory), tone mapped as render's images are
// (exposure, ACES filmic curve, sRGB):
//   reference.png         the reference
//   M_Nspp.png            M = ratio_ltc, ratio_ltc_adaptive, ratio_area, mis, ratio_ltc_denoised,
//                         mis_denoised; N = 1, 4, 16 (those in the lists)
//   error_M_4spp.png      |Y - Y_ref| / max(Y_ref, floor) in false colour (measure.hpp), over the
//                         floor and the occluders
//   error_vs_time.csv     method, spp, seconds, mean relative error, relative RMSE, rays per
//                         pixel, CPU seconds, mean signed error, and the three errors over the
//                         dielectric and over the gold tiles, for every spp of the lists (default
//                         1 .. 64 for (a), (a+) and (d), 1 .. 256 for (b), (c) and (e));
//                         plot_error_vs_time.py draws error_vs_time.png from it
// Printed: the reference's time and its relative standard error; three tables, over all the floor
// pixels, over the dielectric tiles and over the gold tiles, of each method and spp: the shading
// time of the whole image (wall clock on --threads threads, the reference's excluded, and the CPU
// time of the same runs: measure.hpp), rays per pixel and the errors (mean of |e| and RMS of e,
// e = (Y - Y_ref) / max(Y_ref, 0.01 / exposure) of luminance, and mean signed e); the equal-time
// ratios error(a)/error(x), error(b)/error(x), error(c)/error(x), error(e)/error(x) at the times
// of x = (a), (a+) and (d) for K = 1, 4, 16, over all the floor by wall clock and by CPU time,
// over each material by CPU time (report.hpp); and (a)'s, (a+)'s and (d)'s errors split into
// noise and bias by a second render with other seeds at K = 1, 4, 16, with (a+)'s and (d)'s shift
// from (a) (the early stop's and the filter's bias).
// The default run takes about 40 s on 2 idle cores (75 s of CPU time), most of it the reference.
// Exit status 0, 1 if a file could not be written, Embree failed or a value was not finite, 2
// for bad arguments.
//
// Dependencies: GLM, Embree 3 (Debian: libembree-dev), stb_image_write (libstb-dev); the pieces it
// shares with render (examples/common/): cli.hpp, colour.hpp, image.hpp, math.hpp, pinhole.hpp,
// random.hpp, stb.hpp / stb.cpp and threads.hpp.
//
// Source files (examples/shadows/): options.hpp (the command line), scene.hpp (geometry,
// materials, camera), tracer.hpp (Embree: closest hits and shadow rays, their offsets),
// camera.hpp (what each pixel sees), shade_ratio.hpp ((a), (a+), (b), and the pixels of (d)),
// shade_mis.hpp ((c), the pixels of (e), and the reference), denoise.hpp ((d)'s and (e)'s filter),
// measure.hpp (timed renders, errors by region, noise), report.hpp (CSV and tables), this file
// (the flow), plot_error_vs_time.py (the figure).
#include "camera.hpp"
#include "common/cli.hpp"
#include "common/colour.hpp"
#include "common/image.hpp"
#include "common/progress.hpp"
#include "measure.hpp"
#include "options.hpp"
#include "report.hpp"
#include "scene.hpp"
#include "shade_ratio.hpp"
#include "tracer.hpp"

#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

using namespace shadows;

namespace {

bool write_image(const std::filesystem::path& path, const std::vector<dvec3>& img, int W, int H, double exposure) {
    std::vector<std::uint8_t> rgb(img.size() * 3);
    for (std::size_t i = 0; i < img.size(); ++i) ltc_examples::tone_map(img[i], exposure, &rgb[3 * i]);
    return ltc_examples::write_png(path, W, H, rgb);
}

}  // namespace

int main(int argc, char** argv) {
    options opt;
    if (const int r = parse_args(argc, argv, opt); r != 0) return r == 1 ? 0 : 2;
    const int W = opt.width, H = opt.height;
    const double dark_floor = 0.01 / opt.exposure;  // measure.hpp's floor
    const std::filesystem::path out_dir(opt.out);
    if (!ltc_examples::create_output_directory(out_dir)) return 1;

    const scene s;
    std::unique_ptr<tracer> tr;
    try {
        tr = std::make_unique<tracer>(s);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    const std::vector<pixel_hit> hits = trace_camera(s, *tr, W, H);
    std::size_t gold_pixels = 0, floor_pixels = 0, occluder_pixels = 0;
    for (const pixel_hit& h : hits) {
        floor_pixels += h.kind == pixel_hit::floor;
        gold_pixels += in_region(h, region::gold);
        occluder_pixels += h.kind == pixel_hit::occluder;
    }
    std::printf("%d x %d pixels (%zu floor: %zu dielectric, %zu gold; %zu occluder), %u thread%s\n", W, H,
                floor_pixels, floor_pixels - gold_pixels, gold_pixels, occluder_pixels, opt.threads,
                opt.threads == 1 ? "" : "s");
    if (opt.lobes == analytic_model::two_lobes)
        std::printf("(a), (a+), (b), (d): the analytic part from the two-lobe GGX table (--lobes 2)\n");
    if (opt.lobes == analytic_model::ltc_and_cosine)
        std::printf("(a), (a+), (b), (d): the analytic part from the table of an LTC and the cosine (--lobes cosine)\n");

    // The reference: (c) with its own seeds.
    std::fflush(stdout);  // the progress bar goes to stderr
    filter_settings no_filter;  // the reference is (c): no filter, no blockers
    no_filter.radius = 0, no_filter.ltc_correction = false, no_filter.penumbra = false;
    const method_image ref = render_method(s, *tr, hits, W, H, opt.threads, method::mis, opt.reference_spp,
                                           mix_seed(opt.seed, 0x7EFu), opt.lobes, no_filter, false, 1, "reference");
    std::size_t nonfinite = ref.nonfinite;
    const noise_measure ref_noise = reference_noise(hits, ref, dark_floor);
    std::printf("reference: %d iterations, %.2f s; its relative standard error over the floor: mean %.2f%%, "
                "RMS %.2f%%\n",
                opt.reference_spp, ref.seconds, 100 * ref_noise.mean, 100 * ref_noise.rms);
    bool ok = write_image(out_dir / "reference.png", ref.img, W, H, opt.exposure);

    // The sweep.
    std::vector<sweep_row> rows;
    std::vector<std::uint8_t> rgb(hits.size() * 3);
    std::vector<seed_pair> pairs;  // (a), (a+) and (d) at K = 1, 4, 16, for their noise below
    const std::vector<int>* lists[] = {&opt.spp,     &opt.adaptive_spp, &opt.area_spp,
                                       &opt.mis_spp, &opt.denoised_spp, &opt.denoised_mis_spp};
    const method methods[] = {method::ratio_ltc, method::ratio_ltc_adaptive, method::ratio_area,
                              method::mis,       method::ratio_ltc_denoised, method::mis_denoised};
    std::size_t sweep_done = 0, sweep_total = 0;
    for (const std::vector<int>* l : lists) sweep_total += l->size();
    ltc_examples::progress sweep("sweep", "renders");
    sweep.update(0, sweep_total);
    for (int k = 0; k < 6; ++k) {
        const method m = methods[k];
        for (int spp : *lists[k]) {
            const method_image r =
                render_method(s, *tr, hits, W, H, opt.threads, m, spp, opt.seed, opt.lobes, opt.filter, opt.screen_points);
            nonfinite += r.nonfinite;
            sweep.update(++sweep_done, sweep_total);
            const std::string stem = std::string(method_name(m)) + "_" + std::to_string(spp) + "spp";
            const region_errors e = measure_error(hits, r.img, ref.img, dark_floor, spp == 4 ? &rgb : nullptr);
            rows.push_back({m, spp, r.seconds, r.cpu_seconds, r.rays_per_pixel, e});
            if (spp == 4) ok = ltc_examples::write_png(out_dir / ("error_" + stem + ".png"), W, H, rgb) && ok;
            if (spp != 1 && spp != 4 && spp != 16) continue;
            ok = write_image(out_dir / (stem + ".png"), r.img, W, H, opt.exposure) && ok;
            if (m == method::ratio_ltc || m == method::ratio_ltc_adaptive || m == method::ratio_ltc_denoised)
                pairs.push_back({m, spp, r.img, {}});
        }
    }
    ok = write_csv(out_dir / "error_vs_time.csv", rows) && ok;
    for (region g : regions) print_table(rows, g);
    print_equal_time(rows, false, region::floor);
    for (region g : regions) print_equal_time(rows, true, g);

    // (a)'s, (a+)'s and (d)'s errors split into their noise and bias: a second render of each with other seeds.
    ltc_examples::progress second_renders("second seeds", "renders");
    std::size_t second_done = 0;
    second_renders.update(0, pairs.size());
    for (seed_pair& p : pairs) {
        const method_image second = render_method(s, *tr, hits, W, H, opt.threads, p.which, p.spp,
                                                  mix_seed(opt.seed, 0x5EEDu), opt.lobes, opt.filter, opt.screen_points, 1);
        p.second = second.img;
        nonfinite += second.nonfinite;
        second_renders.update(++second_done, pairs.size());
    }
    print_noise_bias(pairs, hits, ref.img, dark_floor, ref_noise.rms);
    std::printf("\nnon-finite pixel values (made black; expected 0): %zu\n", nonfinite);
    return ok && nonfinite == 0 ? 0 : 1;
}
