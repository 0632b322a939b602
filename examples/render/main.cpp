// render -- a small CPU renderer: LTC shading of polygonal lights next to its Monte Carlo reference.
//
//   render [--width W] [--height H] [--spp N] [--threads K] [--out DIR] [--exposure E]
//          [--seed S] [--texture FILE | --no-texture] [--texture-radiance R]
//          [--textured-method fetch|quick_cells|exact_cells|all] [--cells N] [--lobes 1|2|cosine]
//          [--shapes] [--help]
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
// the fitted LTC tables are least accurate (see the README's error tables).
//
// Images, written into --out (default: the current directory):
//   ltc.png        per pixel and light, ltc::shade<ltc::ggx::ltc_and_cosine> of an
//                  ltc::polygon_light, one-sided towards its front (specular + diffuse; default
//                  horizon clipping): the default GGX table of an LTC and the clamped cosine (the
//                  cosine's integral the diffuse term's form factor), the exact polygon integral,
//                  Schlick's Fresnel through the table's magnitude and fresnel terms (Hill 2016);
//                  for the textured light ltc::shade<ltc::ggx::one_lobe> of an
//                  ltc::textured_quad_light (the one-lobe table, the same Fresnel, specular and
//                  diffuse) with the ltc::textured_policy of --textured-method:
//                    fetch        (the default) I_D I_L: the exact polygon integral times one
//                                 trilinear fetch into the prefiltered ltc::light_texture (the
//                                 paper, sections 5.2-5.4);
//                    quick_cells  16 to 22 cells of the texture's cell pyramid, each cell's
//                                 I_D exact, its radiance the mean of its texels or, in a cell
//                                 wider than the lobe, a fetch (ltc/shading/quick_cells.hpp);
//                    exact_cells  the texel-constant texture over adaptive cells
//                                 (ltc/shading/textured_cells.hpp), a budget of --cells cells
//                                 (default 64): the
//                                 exact integral of the texel-constant texture once every cell
//                                 is a texel, and converging to it as the budget grows;
//                    all          the three (below). float.
//                  With --lobes 2 the polygonal lights by ltc::shade<ltc::ggx::two_lobes> instead:
//                  the opt-in two-lobe GGX table, the sum of two exactly integrated lobes (same
//                  lights, diffuse term and Fresnel; about 1.6x the cost). The textured light
//                  and the --shapes lights stay as they are (one lobe). The images keep their
//                  names (run it with another --out to keep the default run's): ltc.png and
//                  error.png are then the two-lobe render's; reference.png and textured_error.png
//                  do not change. --lobes 1 likewise with ltc::shade<ltc::ggx::one_lobe>, the
//                  paper's single LTC (the default before the model of an LTC and the cosine;
//                  0.96-1.00x the default's cost in the README's benchmark).
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
// With --lobes 2 the LTC and batch times, the reference / LTC ratio and the statistics of all
// lights and of the polygonal lights alone (overall lines and per-tile means) are those of the
// two-lobe render: a line after the scene's says so, and the LTC time and the headings say
// "polygonal lights with two lobes" (--lobes 1: "with one lobe"). The default run's lines have
// the format they had before --lobes; their values are the default table's.
// --shapes (shapes.hpp, shapes_render.hpp): after the rest, unchanged, a disk, a sphere and a tube
// light alone on the floor: shapes_ltc.png, shapes_reference.png, shapes_error.png, statistics.
// Exit status 0, or 1 if an image could not be written or read or a value was not finite, 2
// for bad arguments. The reference render's progress goes to stderr.
//
// Dependencies: GLM, stb_image_write and stb_image (Debian: libstb-dev, <stb/stb_image_write.h>,
// <stb/stb_image.h>).
//
// Source files (examples/render/): options.hpp (the command line), scene.hpp (floor, materials,
// camera placement) and lights.hpp (the lights), stained_glass.hpp (the default picture),
// camera.hpp (what each pixel sees), shade_ltc.hpp and shade_reference.hpp (the two renders; one
// pixel), ltc_timing.hpp (the timed LTC render of the polygonal lights), textured_methods.hpp (the
// textured light by each method), reference_render.hpp (the timed reference render),
// error_stats.hpp (the statistics) and report.hpp (the error images and printed statistics),
// math.hpp (the shared pieces by their plain names), and this file: the top-level flow. Shared
// with the shadows example (examples/common/): cli.hpp (the command line's common options and
// loop, the output directory), colour.hpp (luminance, tone mapping, false colour), image.hpp
// (texture files in, PNGs out, through stb.hpp / stb.cpp), math.hpp, pinhole.hpp (the camera's
// rays), random.hpp (seeds), threads.hpp (rows on worker threads), progress.hpp (progress on stderr).
#include "camera.hpp"
#include "common/cli.hpp"
#include "common/colour.hpp"
#include "common/image.hpp"
#include "common/threads.hpp"
#include "error_stats.hpp"
#include "lights.hpp"
#include "ltc_timing.hpp"
#include "math.hpp"
#include "options.hpp"
#include "reference_render.hpp"
#include "report.hpp"
#include "scene.hpp"
#include "shapes_render.hpp"
#include "stained_glass.hpp"
#include "textured_methods.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

using namespace render;  // the pieces above

int main(int argc, char** argv) {
    options opt;
    if (const int r = parse_args(argc, argv, opt); r != 0) return r == 1 ? 0 : 2;
    const int W = opt.width, H = opt.height;
    const std::size_t count = static_cast<std::size_t>(W) * H;

    const std::filesystem::path out_dir(opt.out);
    if (!create_output_directory(out_dir)) return 1;

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
    if (opt.lobes == 2)
        std::printf("polygonal lights: the two-lobe GGX table (--lobes 2: ltc::shade<ltc::ggx::two_lobes>)\n");
    if (opt.lobes == 1)
        std::printf("polygonal lights: the one-lobe GGX table (--lobes 1: ltc::shade<ltc::ggx::one_lobe>)\n");

    // The textured light's LTC render by each method of --textured-method (one, or all three
    // with "all"); the first one's is the textured light of ltc.png, error.png and
    // textured_error.png (fetch's with "all").
    std::vector<textured_run> runs = make_textured_runs(opt, tex != nullptr, count);
    const bool compare = runs.size() > 1;  // --textured-method all
    const std::string note = method_note(runs);

    // LTC render: each part timed as the best of 5 runs (it takes milliseconds).
    ltc_timing lt = render_ltc_polygons(s, hits, W, H, opt.threads, opt.lobes);
    std::vector<dvec3>& ltc_poly = lt.poly;
    render_textured_runs(s, hits, W, H, opt.threads, runs);
    print_ltc_times(s, lt, runs, note, floor_pixels, opt.threads);

    std::size_t ltc_nonfinite = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!finite3(ltc_poly[i])) ++ltc_nonfinite, ltc_poly[i] = dvec3(0.0);
        for (textured_run& r : runs)
            if (!finite3(r.ltc[i])) ++ltc_nonfinite, r.ltc[i] = dvec3(0.0);
    }
    const std::vector<dvec3> no_textured_light(runs.empty() ? count : 0, dvec3(0.0));
    const std::vector<dvec3>& ltc_tex = runs.empty() ? no_textured_light : runs[0].ltc;
    std::vector<dvec3> ltc_img(count);
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
        if (opt.shapes) ok = run_shapes(s, hits, floor_pixels, opt, out_dir) && ok;
        return ok && ltc_nonfinite == 0 ? 0 : 1;
    }

    // Reference render.
    const reference_render ref = render_reference(s, hits, W, H, opt);
    print_reference_time(s, ref, opt, lt.seconds + textured_seconds(runs));
    for (std::size_t i = 0; i < count; ++i) tone_map(ref.img[i], opt.exposure, &rgb[3 * i]);
    ok = write_png(out_dir / "reference.png", W, H, rgb) && ok;

    // Error images and statistics.
    ok = report_errors(s, hits, ltc_poly, ltc_img, runs, ref, note, floor_pixels, opt, out_dir, rgb) && ok;
    std::printf("non-finite values: LTC %zu, reference %zu\n", ltc_nonfinite, ref.nonfinite);
    if (opt.shapes) ok = run_shapes(s, hits, floor_pixels, opt, out_dir) && ok;
    return ok && ltc_nonfinite == 0 && ref.nonfinite == 0 ? 0 : 1;
}
