// render -- a small CPU renderer: LTC shading of polygonal lights next to its Monte Carlo reference.
//
//   render [--width W] [--height H] [--spp N] [--threads K] [--out DIR] [--exposure E]
//          [--seed S] [--texture FILE | --no-texture] [--texture-radiance R]
//          [--textured-method fetch|quick_cells|exact_cells|all] [--cells N] [--help]
//
// The scene (z up): a tiled ground plane seen by a pinhole camera 2.8 units above it, lit by two
// one-sided, constant-radiance polygonal lights standing behind the floor, facing the camera and
// tilted 10 degrees towards the floor: a warm 1.2 x 3.4 rectangle leaning 20 degrees (rotated in
// its own plane; left) and a cool irregular pentagon (right); and between them a one-sided
// textured quad light (paper sections 5.2-5.4) in the same plane: by default a procedural
// stained-glass window (192 x 256 texels, generated here: a pointed arch of coloured glass
// cells and a rose, joined by dark lead lines, on a black -- non-emitting -- surround), or any
// image given by --texture (loaded with stb_image). The lights are drawn as emitters where the
// camera sees them (their radiance, the textured one with its texel-constant texture -- see
// reference.png below --, the same in both renders); there are no shadows (nothing in the scene
// can occlude a light).
//
// Floor layout: four material stripes running away from the camera, crossed by five bands of
// roughness, so that each light's reflection runs along a stripe boundary through every band:
//   stripes, left to right   dielectric | gold | dielectric | copper
//                            (the rectangle's reflection straddles the first boundary, the
//                            textured light's the middle one, the pentagon's the last one)
//   bands, near to far       roughness 0.9, 0.7, 0.5, 0.3, 0.1 (alpha = roughness^2)
//   dielectric: F0 = 0.04 and a Lambertian albedo 0.5; gold, copper: coloured F0, no diffuse;
//   thin grout lines between the tiles (a rough, dark dielectric).
// The camera sees the floor at theta_v = 50 to 76 degrees from its normal: grazing angles, where
// the fitted LTC table is least accurate (see the README's error table).
//
// Images, written into --out (default: the current directory):
//   ltc.png        per pixel and light, ltc::shade_polygon_light (specular + diffuse; default
//                  horizon clipping, one-sided): the GGX LTC table, the exact polygon integral,
//                  Schlick's Fresnel through the table's magnitude and fresnel terms (Hill
//                  2016); for the textured light ltc::shade_textured_quad_light (the same table
//                  and Fresnel, specular and diffuse) with the ltc::textured_policy of
//                  --textured-method:
//                    fetch        (the default) I_D I_L: the exact polygon integral times one
//                                 trilinear fetch into the prefiltered ltc::light_texture (the
//                                 paper, sections 5.2-5.4);
//                    quick_cells  the texel-constant texture over 16 adaptive cells of the
//                                 texture's cell pyramid, each cell's I_D exact and its radiance
//                                 the mean of its texels (ltc/shading/textured_cells.hpp);
//                    exact_cells  the same with a budget of --cells cells (default 64): the
//                                 exact integral of the texel-constant texture once every cell
//                                 is a texel, and converging to it as the budget grows;
//                    all          the three (below). float.
//   reference.png  the same GGX BRDF integrated without approximation: for every pixel and
//                  polygonal light, two Monte Carlo integrals by ltc::ground_truth::integrate
//                  (BRDF sampling of visible normals + uniform spherical-polygon sampling, balance
//                  heuristic, one direction from each technique per iteration, --spp iterations
//                  each),
//                      A = int_P rho cos dL                 (model ltc::brdf::ggx<double>)
//                      B = int_P rho cos (1 - V.H)^5 dL      (the same, times Schlick's weight)
//                  so that the specular radiance with Schlick's Fresnel is exactly
//                  radiance * (F0 A + (1 - F0) B); the diffuse term is the closed-form
//                  clipped form factor (ltc::form_factor, exact: no approximation to measure
//                  there). For the textured light, ltc::textured_ground_truth::integrate of the
//                  unfiltered, texel-constant texture (each texel's colour over its whole square:
//                  ltc::nearest_image_lookup, in textured_light::radiance; also what the camera
//                  sees of the emitter), --spp iterations. Texel-constant, not bilinear: that
//                  is the texture the cell methods integrate (exact_cells converges to its
//                  integral as --cells grows, and equals it, to rounding, once every cell is a
//                  texel), so a method's error against this reference is the method's own. With
//                  a bilinearly interpolated texture the reference would be a different,
//                  smoother radiance, and even a converged exact_cells would keep an error --
//                  the difference between the two textures' integrals -- that no budget
//                  removes. The integrals:
//                      S = int_Q L(w) F(V, w) rho cos dw   (lobe brdf_lobe<ggx<double>>, RGB)
//                      D = int_Q L(w) cos / pi dw          (lobe ltc_lobe, M = I: the clamped
//                                                           cosine; only where albedo > 0)
//                  radiance S + albedo D. The estimator weights each sample by a scalar lobe
//                  times the RGB radiance callback L(u, v); Schlick's Fresnel
//                  F = F0 + (1 - F0) (1 - V.H)^5 depends on the direction only, and on the quad
//                  each (u, v) is one direction w = x(u, v) / |x(u, v)|, so the callback returns
//                  L(u, v) F(V, w(u, v)): the same Fresnel as F0 A + (1 - F0) B above, in one
//                  integral, exactly. The directions come from GGX (visible normals) or cosine
//                  sampling and from area sampling of the quad proportional to half uniform,
//                  half texel luminance (texel_distribution: no samples wasted on black texels),
//                  balance heuristic. The diffuse term is sampled too: unlike the constant
//                  lights, int L cos over a texture has no closed form. double. Deterministic:
//                  every pixel, light, integral (and, for the textured light, iteration) has its
//                  own seed, so the image is the same whatever the thread count.
//   error.png      false colour of the relative error of luminance,
//                      e = |Y_ltc - Y_ref| / max(Y_ref, floor),  floor = 0.01 / exposure,
//                  on a fixed scale: 0% dark blue, 5% blue, 10% green, 15% yellow, 20% and
//                  above red. Background and emitters are black.
//   textured_error.png  (with the textured light) the same for the textured light's contribution
//                  alone, |Y_ltc,tex - Y_ref,tex| / max(Y_ref,tex, floor), by --textured-method.
//   With --textured-method all, the textured light is shaded by each method (the reference is
//   computed once: it does not depend on the method); ltc.png, error.png and textured_error.png
//   are then fetch's (those of the default run), and for each method M = fetch, quick_cells,
//   exact_cells:
//   ltc_M.png      the LTC render with the textured light by M,
//   textured_error_M.png  the textured light's error image of M (textured_error_fetch.png is
//                  textured_error.png).
//
// Both renders are tone mapped identically: radiance * exposure, the ACES filmic curve of
// Narkowicz 2015 per channel, clamp to [0, 1], sRGB encoding. One camera ray through each
// pixel centre (no antialiasing: tile edges alias, identically in both images).
//
// Printed: the time of each render and their ratio; error statistics of the LTC render over the
// floor pixels whose reference luminance is at least the floor (mean signed and mean, median,
// 95th percentile and max absolute relative error; mean per tile), the reference's own Monte
// Carlo noise (relative standard error of Y_ref: mean, median, 95th percentile, max) and the
// share of pixels where the LTC differs from the reference by more than 3 standard errors (where
// the difference is the LTC's, not the noise's); the count of non-finite values (expected 0,
// replaced by black and left out of the statistics). With the textured light, these statistics
// come three times: for all lights (the images), for the two polygonal lights alone (the same
// numbers, seeds and images as --no-texture, which renders the scene without the textured
// light), and for the textured light's contribution alone (the floor is then Y_ref,tex >=
// 0.01 / exposure). For the textured light the standard error of Y_ref is exact: the
// luminance of every iteration's RGB value (specular + albedo x diffuse) enters the variance.
// With --textured-method all: each method's LTC time for the textured light (best of 5, and
// its ratio to fetch's), the textured light's statistics once per method (the same pixels and
// reference noise for all), then the methods side by side: one line each (time; mean, median,
// p95, max, mean signed error; share beyond 3 standard errors) and the per-tile means of the
// three. The other lines are fetch's. With all, or one method other than fetch, the LTC time
// and the headings name the method of ltc.png ("textured light by exact_cells (64 cells)"); the
// default run's lines are as they were before --textured-method.
// Exit status 0, or 1 if an image could not be written or read or a value was not finite, 2
// for bad arguments. A progress bar with an ETA for the reference render goes to stderr.
//
// Dependencies: GLM, stb_image_write and stb_image (Debian: libstb-dev, <stb/stb_image_write.h>,
// <stb/stb_image.h>).
//
// Source files (examples/render/): options.hpp (the command line), scene.hpp (floor, materials,
// camera placement) and lights.hpp (the lights), image.hpp (texture files in, PNGs out, through
// stb.hpp / stb.cpp) and stained_glass.hpp (the default picture), camera.hpp (what each pixel
// sees), shade_ltc.hpp and shade_reference.hpp (the two renders), colour.hpp (luminance, tone
// mapping, false colour), error_stats.hpp (the statistics), threads.hpp (rows on worker threads,
// progress bar), and this file: the top-level flow.
#include "camera.hpp"
#include "colour.hpp"
#include "error_stats.hpp"
#include "image.hpp"
#include "lights.hpp"
#include "math.hpp"
#include "options.hpp"
#include "scene.hpp"
#include "shade_ltc.hpp"
#include "shade_reference.hpp"
#include "stained_glass.hpp"
#include "threads.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

using namespace render;  // the pieces above

namespace {

/// The textured light's LTC render by one method (--textured-method).
struct textured_run {
    ltc::textured_policy policy;
    std::string label;  // "fetch", "quick_cells (16 cells)", "exact_cells (N cells)"
    std::vector<dvec3> ltc;  // its contribution (and its emitter)
    double seconds = INFINITY;  // best of 5
};

/// --textured-method all: the textured light's statistics of every method side by side (the same
/// reference and floor pixels for all): LTC time and error of luminance, then the per-tile means.
void print_comparison(const scene& s, const std::vector<textured_run>& runs, const std::vector<error_stats>& st,
                      std::size_t floor_pixels, unsigned threads) {
    std::printf("\n=== the textured light alone, the methods side by side (the same reference, the same %zu floor "
                "pixels) ===\n",
                st[0].rel.size());
    std::printf("  %-24s %10s %9s   |relative error|: %6s %7s %7s %7s   %7s %8s\n", "method", "LTC time", "ns/pixel",
                "mean", "median", "p95", "max", "signed", ">3 s.e.");
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const error_stats& e = st[k];
        std::printf("  %-24s %8.4f s %9.0f   %16s %5.2f%% %6.2f%% %6.2f%% %6.1f%%   %+6.2f%% %7.1f%%\n",
                    runs[k].label.c_str(), runs[k].seconds,
                    runs[k].seconds * 1e9 * threads / static_cast<double>(floor_pixels), "", 100 * mean_of(e.rel),
                    100 * percentile(e.rel, 0.5), 100 * percentile(e.rel, 0.95), 100 * percentile(e.rel, 1.0),
                    100 * mean_of(e.signed_rel),
                    e.rel.empty() ? 0.0 : 100.0 * static_cast<double>(e.significant) / static_cast<double>(e.rel.size()));
    }
    std::printf("  (LTC time: best of 5, %u thread%s; ns/pixel: of one thread per floor pixel; signed: mean signed\n"
                "  relative error; >3 s.e.: pixels where |Y_ltc - Y_ref| > 3 standard errors of the reference)\n",
                threads, threads == 1 ? "" : "s");
    std::printf("\nper tile, mean |relative error| in %%,");
    for (std::size_t k = 0; k < runs.size(); ++k)
        std::printf("%s%s", k ? " / " : " ", method_name(runs[k].policy.method));
    std::printf("; bands far to near, stripes left to right:\n  roughness");
    for (const char* name : s.column_names) std::printf(" %20s", name);
    std::printf("\n");
    for (int b = scene::bands - 1; b >= 0; --b) {
        std::printf("  %9.2f", static_cast<double>(s.roughness[b]));
        for (int c = 0; c < scene::columns; ++c) {
            const std::size_t m = static_cast<std::size_t>(b * scene::columns + c);
            std::string cell;
            for (std::size_t k = 0; k < runs.size(); ++k) {
                char v[24];
                if (st[k].tile_rel[m].empty())
                    std::snprintf(v, sizeof v, "-");
                else
                    std::snprintf(v, sizeof v, "%.1f", 100 * mean_of(st[k].tile_rel[m]));
                cell += (k ? " / " : "") + std::string(v);
            }
            std::printf(" %20s", cell.c_str());
        }
        std::printf("\n");
    }
}

}  // namespace

int main(int argc, char** argv) {
    options opt;
    if (const int r = parse_args(argc, argv, opt); r != 0) return r == 1 ? 0 : 2;
    if (opt.threads == 0) opt.threads = std::max(1u, std::thread::hardware_concurrency());
    const int W = opt.width, H = opt.height;
    const std::size_t count = static_cast<std::size_t>(W) * H;

    std::error_code ec;
    const std::filesystem::path out_dir(opt.out);
    std::filesystem::create_directories(out_dir, ec);
    if (!std::filesystem::is_directory(out_dir, ec)) {
        std::fprintf(stderr, "error: cannot create the output directory %s\n", opt.out.c_str());
        return 1;
    }

    scene s;
    double prefilter_seconds = 0;
    if (opt.textured) {
        image picture;
        if (opt.texture.empty())
            picture = stained_glass(192, 256);
        else if (!load_image(opt.texture, picture))
            return 1;
        const auto t0 = clock_type::now();
        try {
            s.add_textured_light(std::move(picture), static_cast<float>(opt.texture_radiance));
        } catch (const std::exception& e) {
            std::fprintf(stderr, "error: cannot prefilter the texture: %s\n", e.what());
            return 1;
        }
        prefilter_seconds = seconds_since(t0);
    }
    const textured_light* tex = s.textured.get();
    const std::vector<pixel_hit> hits = trace_camera(s, W, H);
    std::size_t floor_pixels = 0;
    for (const auto& h : hits) floor_pixels += h.kind == pixel_hit::floor;
    std::printf("%d x %d pixels (%zu on the floor), %zu lights (", W, H, floor_pixels, s.lights.size() + (tex ? 1 : 0));
    for (std::size_t k = 0; k < s.lights.size(); ++k)
        std::printf("%s%s, %zu vertices", k ? "; " : "", s.lights[k].name, s.lights[k].vertices.size());
    if (tex)
        std::printf("; %s, %d x %d texels", tex->name, tex->picture.width, tex->picture.height);
    std::printf("), %u thread%s\n", opt.threads, opt.threads == 1 ? "" : "s");
    if (tex)
        std::printf("textured light: %s, %.2f x %.2f units, white = radiance %g; prefiltered in %.3f s "
                    "(%d levels)\n",
                    opt.texture.empty() ? "procedural stained glass" : opt.texture.c_str(), 2.0 * tex->half_width,
                    2.0 * tex->half_height, opt.texture_radiance, prefilter_seconds, tex->prefiltered->level_count());

    // The textured light's LTC render by each method of --textured-method (one, or all three
    // with "all"); the first one's is the textured light of ltc.png, error.png and
    // textured_error.png (fetch's with "all").
    std::vector<textured_run> runs;
    for (std::size_t k = 0; tex && k < opt.textured_methods.size(); ++k) {
        textured_run r;
        r.policy.method = opt.textured_methods[k];
        r.policy.budget.max_cells = opt.cells;
        r.label = method_name(r.policy.method);
        if (r.policy.method != ltc::textured_method::fetch)
            r.label += " (" +
                       std::to_string(r.policy.method == ltc::textured_method::quick_cells
                                          ? ltc::textured_policy::quick_cells_budget
                                          : opt.cells) +
                       " cells)";
        r.ltc.assign(count, dvec3(0.0));
        runs.push_back(std::move(r));
    }
    const bool compare = runs.size() > 1;  // --textured-method all
    // " by quick_cells (16 cells)" after "textured light" where the method is named: with all, or
    // with one method other than the default fetch (the default run's lines are left as they were).
    const std::string method_note =
        !runs.empty() && (compare || runs[0].policy.method != ltc::textured_method::fetch) ? " by " + runs[0].label
                                                                                            : "";

    // LTC render: each part timed as the best of 5 runs (it takes milliseconds).
    std::vector<dvec3> ltc_poly(count), ltc_img(count);
    double ltc_seconds = INFINITY;
    for (int run = 0; run < 5; ++run) {
        const auto t0 = clock_type::now();
        for_each_row(H, opt.threads, [&](int y) {
            for (int x = 0; x < W; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * W + x;
                ltc_poly[i] = dvec3(shade_ltc(s, hits[i]));
            }
        });
        ltc_seconds = std::min(ltc_seconds, seconds_since(t0));
    }
    // The same polygonal lights a row of pixels at a time through the batch API (SIMD lanes).
    std::vector<dvec3> ltc_batch(count);
    double batch_seconds = INFINITY;
    for (int run = 0; run < 5; ++run) {
        const auto t0 = clock_type::now();
        for_each_row(H, opt.threads, [&](int y) {
            const std::size_t row = static_cast<std::size_t>(y) * W;
            std::vector<vec3> px(static_cast<std::size_t>(W));
            shade_ltc_batch(s, hits.data() + row, px.size(), px.data());
            for (int x = 0; x < W; ++x) ltc_batch[row + x] = dvec3(px[static_cast<std::size_t>(x)]);
        });
        batch_seconds = std::min(batch_seconds, seconds_since(t0));
    }
    double batch_diff = 0, peak = 0;
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c) {
            batch_diff = std::max(batch_diff, std::abs(ltc_batch[i][c] - ltc_poly[i][c]));
            if (hits[i].kind == pixel_hit::floor) peak = std::max(peak, ltc_poly[i][c]);
        }
    for (textured_run& r : runs)
        for (int run = 0; run < 5; ++run) {
            const auto t0 = clock_type::now();
            for_each_row(H, opt.threads, [&](int y) {
                for (int x = 0; x < W; ++x) {
                    const std::size_t i = static_cast<std::size_t>(y) * W + x;
                    r.ltc[i] = dvec3(shade_ltc_textured(s, hits[i], r.policy));
                }
            });
            r.seconds = std::min(r.seconds, seconds_since(t0));
        }
    const double ltc_tex_seconds = runs.empty() ? 0.0 : runs[0].seconds;
    const auto ns_per_floor_pixel = [&](double seconds) {
        return seconds * 1e9 * opt.threads / static_cast<double>(floor_pixels);
    };
    if (!tex) {
        std::printf("LTC render:       %9.4f s  (best of 5; %.0f ns of one thread per floor pixel and light)\n",
                    ltc_seconds,
                    ltc_seconds * 1e9 * opt.threads / (static_cast<double>(floor_pixels) * s.lights.size()));
    } else {
        std::printf("LTC render:       %9.4f s  (best of 5 of each part: polygonal lights %.4f s, %.0f ns of one "
                    "thread per floor pixel and light;\n"
                    "                                textured light%s %.4f s, %.0f ns per floor pixel)\n",
                    ltc_seconds + ltc_tex_seconds, ltc_seconds,
                    ltc_seconds * 1e9 * opt.threads / (static_cast<double>(floor_pixels) * s.lights.size()),
                    method_note.c_str(), ltc_tex_seconds, ns_per_floor_pixel(ltc_tex_seconds));
    }

    std::printf("LTC render, batch: %9.4f s  (the polygonal lights through ltc::batch::shade_polygon_light: %.1fx as "
                "fast;\n                                largest difference to the point-by-point render %.1e, floor "
                "values up to %.2f)\n",
                batch_seconds, ltc_seconds / batch_seconds, batch_diff, peak);
    if (compare) {
        std::printf("LTC render, the textured light by each method (best of 5 each; ltc_<method>.png):\n");
        for (const textured_run& r : runs)
            std::printf("  %-24s %9.4f s  %7.0f ns of one thread per floor pixel  %6.1fx the time of fetch\n",
                        r.label.c_str(), r.seconds, ns_per_floor_pixel(r.seconds), r.seconds / runs[0].seconds);
    }

    std::size_t ltc_nonfinite = 0, ref_nonfinite = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!finite3(ltc_poly[i])) ++ltc_nonfinite, ltc_poly[i] = dvec3(0.0);
        for (textured_run& r : runs)
            if (!finite3(r.ltc[i])) ++ltc_nonfinite, r.ltc[i] = dvec3(0.0);
    }
    const std::vector<dvec3> no_textured_light(runs.empty() ? count : 0, dvec3(0.0));
    const std::vector<dvec3>& ltc_tex = runs.empty() ? no_textured_light : runs[0].ltc;
    for (std::size_t i = 0; i < count; ++i) ltc_img[i] = ltc_poly[i] + ltc_tex[i];

    std::vector<std::uint8_t> rgb(count * 3);
    for (std::size_t i = 0; i < count; ++i) tone_map(ltc_img[i], opt.exposure, &rgb[3 * i]);
    bool ok = write_png(out_dir / "ltc.png", W, H, rgb);
    for (std::size_t k = 0; compare && k < runs.size(); ++k) {
        for (std::size_t i = 0; i < count; ++i) tone_map(ltc_poly[i] + runs[k].ltc[i], opt.exposure, &rgb[3 * i]);
        ok = write_png(out_dir / ("ltc_" + std::string(method_name(runs[k].policy.method)) + ".png"), W, H, rgb) && ok;
    }

    if (opt.spp == 0) {
        std::printf("non-finite values: LTC %zu\n", ltc_nonfinite);
        return ok && ltc_nonfinite == 0 ? 0 : 1;
    }

    // Reference render.
    std::fflush(stdout);  // the progress bar goes to stderr
    std::vector<reference_pixel> ref(count);
    const auto t0 = clock_type::now();
    std::vector<long long> row_cost(static_cast<std::size_t>(H), 0);  // floor pixels per row
    for (std::size_t i = 0; i < count; ++i)
        row_cost[i / static_cast<std::size_t>(W)] += hits[i].kind == pixel_hit::floor;
    for_each_row(
        H, opt.threads,
        [&](int y) {
            for (int x = 0; x < W; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * W + x;
                ref[i] = shade_reference(s, hits[i], mix_seed(opt.seed, i), opt.spp);
            }
        },
        "reference", &row_cost);
    const double ref_seconds = seconds_since(t0);
    if (!tex)
        std::printf("reference render: %9.4f s  (%d iterations x 2 directions x 2 integrals per pixel and light, "
                    "%u threads)\n",
                    ref_seconds, opt.spp, opt.threads);
    else
        std::printf("reference render: %9.4f s  (%d iterations x 2 directions x 2 integrals per pixel and polygonal "
                    "light,\n"
                    "                                x 1 or 2 integrals (specular; diffuse where albedo > 0) for the "
                    "textured light, %u threads)\n",
                    ref_seconds, opt.spp, opt.threads);
    std::printf("reference / LTC:  %9.0f x\n", ref_seconds / (ltc_seconds + ltc_tex_seconds));

    std::vector<dvec3> ref_poly(count), ref_tex(count), ref_img(count);
    std::vector<double> var_poly(count), var_tex(count), var_all(count);
    for (std::size_t i = 0; i < count; ++i) {
        reference_pixel& p = ref[i];
        if (!finite3(p.radiance) || !std::isfinite(p.luminance_variance))
            ++ref_nonfinite, p.radiance = dvec3(0.0), p.luminance_variance = 0;
        if (!finite3(p.textured) || !std::isfinite(p.textured_variance))
            ++ref_nonfinite, p.textured = dvec3(0.0), p.textured_variance = 0;
        ref_poly[i] = p.radiance;
        ref_tex[i] = p.textured;
        ref_img[i] = p.radiance + p.textured;
        var_poly[i] = p.luminance_variance;
        var_tex[i] = p.textured_variance;
        var_all[i] = p.luminance_variance + p.textured_variance;  // independent seeds
    }
    for (std::size_t i = 0; i < count; ++i) tone_map(ref_img[i], opt.exposure, &rgb[3 * i]);
    ok = write_png(out_dir / "reference.png", W, H, rgb) && ok;

    // Error images and statistics.
    const double floor = dark_floor / opt.exposure;
    const error_stats all = measure_error(hits, ltc_img, ref_img, var_all, floor, rgb);
    ok = write_png(out_dir / "error.png", W, H, rgb) && ok;
    if (!tex) {
        std::printf("\n");
        print_error(s, all, floor);
    } else {
        // The textured light alone, by each method, against the one reference.
        std::vector<error_stats> tex_stats;
        for (const textured_run& r : runs) {
            tex_stats.push_back(measure_error(hits, r.ltc, ref_tex, var_tex, floor, rgb));
            if (tex_stats.size() == 1) ok = write_png(out_dir / "textured_error.png", W, H, rgb) && ok;
            if (compare)
                ok = write_png(out_dir / ("textured_error_" + std::string(method_name(r.policy.method)) + ".png"), W,
                               H, rgb) &&
                     ok;
        }
        const error_stats poly_stats = measure_error(hits, ltc_poly, ref_poly, var_poly, floor, rgb);
        std::printf("\n=== all lights (ltc.png, reference.png, error.png%s%s) ===\n",
                    method_note.empty() ? "" : "; the textured light", method_note.c_str());
        print_error(s, all, floor);
        std::printf("\n=== the polygonal lights alone (rectangle + pentagon: the statistics of --no-texture) ===\n");
        print_error(s, poly_stats, floor);
        if (!compare) {
            std::printf("\n=== the textured light alone%s (its contribution to the floor: textured_error.png) ===\n",
                        method_note.c_str());
            print_error(s, tex_stats[0], floor, "Y_ref,tex");
        } else {
            for (std::size_t k = 0; k < runs.size(); ++k) {
                const char* name = method_name(runs[k].policy.method);
                std::printf("\n=== the textured light alone by %s (its contribution to the floor: textured_error_%s.png%s) "
                            "===\n",
                            runs[k].label.c_str(), name, k == 0 ? ", = textured_error.png" : "");
                print_error(s, tex_stats[k], floor, "Y_ref,tex");
            }
            print_comparison(s, runs, tex_stats, floor_pixels, opt.threads);
        }
    }
    std::printf("non-finite values: LTC %zu, reference %zu\n", ltc_nonfinite, ref_nonfinite);
    return ok && ltc_nonfinite == 0 && ref_nonfinite == 0 ? 0 : 1;
}
