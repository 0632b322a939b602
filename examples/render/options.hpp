// render/options.hpp -- the command line: the options, their defaults, --help and the parser.
#pragma once

#include "common/cli.hpp"

#include <ltc/shading/lights/textured_quad_light.hpp>

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace render {

/// The name of a textured method, as --textured-method spells it (and the image names use).
inline const char* method_name(ltc::textured_method m) {
    switch (m) {
        case ltc::textured_method::quick_cells: return "quick_cells";
        case ltc::textured_method::exact_cells: return "exact_cells";
        default: return "fetch";
    }
}

/// " with two lobes" after "polygonal lights" where --lobes 2 shades them, " with one lobe" for
/// --lobes 1; "" for the default, --lobes cosine (stored as lobes = 3), whose lines are as they were.
inline const char* lobes_note(int lobes) {
    return lobes == 2 ? " with two lobes" : lobes == 1 ? " with one lobe" : "";
}

/// The --lobes argument that gives `lobes` (" --lobes 2", " --lobes 1"; "" for the default).
inline const char* lobes_option(int lobes) { return lobes == 2 ? " --lobes 2" : lobes == 1 ? " --lobes 1" : ""; }

struct options : ltc_examples::image_options {  // --width, --height, --threads, --out, --seed, --exposure
    options() : image_options(256, 160) {}
    int spp = 2048;  // MIS iterations per pixel, light and integral
    bool textured = true;      // the textured light (--no-texture: the two polygonal lights only)
    std::string texture;       // image file of the textured light; empty: the stained glass
    double texture_radiance = 8.0;  // radiance of a white texel
    // --textured-method: the methods (the ltc::textured_policy of the ltc::textured_quad_light) to
    // render the textured light with; one, or all three (fetch, quick_cells, exact_cells) with
    // --textured-method all.
    std::vector<ltc::textured_method> textured_methods{ltc::textured_method::fetch};
    std::size_t cells = 64;  // --cells: exact_cells' budget (ltc::cell_budget::max_cells)
    bool shapes = false;     // --shapes: the disk, sphere and tube lights' section (shapes_render.hpp)
    // --lobes: the model of ltc::shade for the polygonal lights in ltc.png, 1 (ltc::ggx::one_lobe)
    // or 2 (ltc::ggx::two_lobes) or 3 for --lobes cosine, the default (ltc::ggx::ltc_and_cosine,
    // the table of an LTC and the cosine); the textured light and the --shapes lights keep one
    // lobe (ltc::ggx::one_lobe).
    int lobes = 3;
};

inline void print_help(const char* argv0) {
    std::printf(
        "usage: %s [--width W] [--height H] [--spp N] [--threads K] [--out DIR] [--exposure E]\n"
        "          [--seed S] [--texture FILE | --no-texture] [--texture-radiance R]\n"
        "          [--textured-method fetch|quick_cells|exact_cells|all] [--cells N] [--lobes 1|2|cosine]\n"
        "          [--shapes] [--help]\n"
        "\n"
        "Renders a tiled floor (GGX dielectric, gold and copper; roughness 0.1 .. 0.9) lit by a\n"
        "rotated rectangular light, a pentagonal light and, between them, a textured quad light (a\n"
        "procedural stained-glass window, or FILE), twice: with LTC (ltc::shade of each\n"
        "ltc::polygon_light with the model of --lobes, and of the ltc::textured_quad_light by\n"
        "--textured-method, by default the prefiltered-texture fetch I_D I_L) and with a Monte\n"
        "Carlo reference of the same GGX BRDF with Schlick's Fresnel\n"
        "(ltc::ground_truth::integrate, BRDF and light sampling with MIS, the diffuse term in closed\n"
        "form; for the textured light ltc::textured_ground_truth::integrate of the texel-constant\n"
        "texture -- each texel's colour over its whole square, ltc::nearest_image_lookup: the\n"
        "texture the exact cell integrals integrate -- specular and diffuse), and writes into DIR:\n"
        "  ltc.png             the LTC render\n"
        "  reference.png       the Monte Carlo reference\n"
        "  error.png           relative error of luminance, |Y_ltc - Y_ref| / max(Y_ref, 0.01 / E), on\n"
        "                      a fixed scale: 0%% dark blue, 5%% blue, 10%% green, 15%% yellow, 20%% and\n"
        "                      above red; background and emitters black\n"
        "  textured_error.png  the same for the textured light's contribution alone (not written\n"
        "                      with --no-texture)\n"
        "  with --textured-method all, also for each method M (fetch, quick_cells, exact_cells):\n"
        "  ltc_M.png           the LTC render with the textured light shaded by M\n"
        "  textured_error_M.png  the textured light's error image of M\n"
        "                      (ltc.png, error.png and textured_error.png are then those of fetch)\n"
        "It prints the render times, error statistics over the floor pixels with Y_ref >= 0.01 / E\n"
        "(mean, median, 95th percentile, max; per tile) and the reference's own Monte Carlo noise:\n"
        "for all lights, for the two polygonal lights alone (the numbers of --no-texture) and for\n"
        "the textured light's contribution alone (with --textured-method all: for each method,\n"
        "against the same reference, with its LTC time, then side by side).\n"
        "\n"
        "  --width W        image width in pixels (default 256)\n"
        "  --height H       image height in pixels (default 160)\n"
        "  --spp N          Monte Carlo iterations per pixel, light and integral (default 2048; each\n"
        "                   draws one BRDF and one light direction; two integrals per polygonal\n"
        "                   light, for Schlick's Fresnel; one specular integral for the textured\n"
        "                   light, Fresnel included, and one diffuse integral where albedo > 0);\n"
        "                   0 renders the LTC image only\n"
        "  --threads K      worker threads (default: all hardware threads); the images do not\n"
        "                   depend on it\n"
        "  --out DIR        output directory, created if needed (default: the current directory)\n"
        "  --exposure E     linear exposure before the tone curve (default 1)\n"
        "  --seed S         base seed of the reference (default 1)\n"
        "  --texture FILE   the textured light's picture: a PNG (or any image stb_image reads: JPEG,\n"
        "                   BMP, TGA, ...), 8-bit sRGB converted to linear, times its alpha (transparent\n"
        "                   texels emit nothing); images over 1024 texels on a side are box-filtered\n"
        "                   down by an integer factor. The quad keeps the image's aspect ratio, within\n"
        "                   2.6 x 3.2 units. Default: a procedural stained-glass window, 192 x 256\n"
        "  --no-texture     leave the textured light out: the scene, images and statistics of the two\n"
        "                   polygonal lights alone\n"
        "  --texture-radiance R  radiance of a white texel (default 8; the polygonal lights have\n"
        "                   radiance 6 times their colour)\n"
        "  --textured-method M  how the LTC render integrates the textured light\n"
        "                   (ltc::textured_policy):\n"
        "                     fetch        I_D I_L, one fetch into the prefiltered texture (the paper,\n"
        "                                  sections 5.2-5.4; the default)\n"
        "                     quick_cells  16 to 22 cells of the texture's cell pyramid, each cell's\n"
        "                                  I_D exact, its radiance the mean of its texels or a fetch\n"
        "                                  (ltc/shading/quick_cells.hpp); two kernel calls\n"
        "                     exact_cells  the texel-constant texture over adaptive cells, a budget\n"
        "                                  of --cells cells (converges to the\n"
        "                                  exact integral of the texel-constant texture)\n"
        "                     all          the three, each timed and measured against the same\n"
        "                                  reference (computed once)\n"
        "  --cells N        exact_cells' budget: adaptive cells at most (default 64; at least 1)\n"
        "  --lobes L        the LTC table of the two polygonal lights in ltc.png: cosine, the default\n"
        "                   (ltc::shade<ltc::ggx::ltc_and_cosine>: an LTC and the clamped cosine, one\n"
        "                   LTC integral), 1, the paper's single LTC (ltc::shade<ltc::ggx::one_lobe>),\n"
        "                   or 2, the opt-in two-lobe GGX table (ltc::shade<ltc::ggx::two_lobes>:\n"
        "                   the sum of two exactly integrated lobes, about 1.6x the cost). The\n"
        "                   textured light and the --shapes lights stay as they are (one lobe). The\n"
        "                   images keep their names (give another --out to keep both runs'); the LTC\n"
        "                   and batch times, error images and statistics are then those of that table.\n"
        "  --shapes         also a separate section: the floor lit by a disk, a sphere and a tube light\n"
        "                   alone (ltc::shade<ltc::ggx::one_lobe> of an ltc::disk_light, sphere_light\n"
        "                   and tube_light against Monte Carlo of the real GGX, --spp / 2 iterations):\n"
        "                   shapes_ltc.png, shapes_reference.png, shapes_error.png and their\n"
        "                   statistics, printed last\n"
        "  --help, -h       this text\n"
        "\n"
        "Floor: stripes dielectric | gold | dielectric | copper (left to right), crossed by bands of\n"
        "roughness 0.9, 0.7, 0.5, 0.3, 0.1 (near to far). Tone mapping, the same for both renders:\n"
        "exposure, the ACES filmic curve (Narkowicz 2015), clamp, sRGB. The default run takes about\n"
        "35 s on 2 cores (about 25 s with --no-texture). The reference's progress goes to stderr:\n"
        "a bar on a terminal, else a line per tenth.\n",
        argv0);
}

/// Returns 0 to go on, 1 after --help, 2 on an error (common/cli.hpp).
inline int parse_args(int argc, char** argv, options& o) {
    using ltc_examples::option_status;
    const auto flag = [&](const std::string& a) {  // the options without a value
        if (a == "--shapes")
            o.shapes = true;
        else if (a == "--no-texture")
            o.textured = false;
        else
            return false;
        return true;
    };
    const auto option = [&](const std::string& a, const ltc_examples::option_value& v) {
        if (a == "--spp") {
            if (!v.integer_in(0, 1e8)) return option_status::bad;
            o.spp = static_cast<int>(v.number);
        } else if (a == "--texture") {
            o.texture = v.text;
            o.textured = true;
        } else if (a == "--textured-method") {
            const std::string m = v.text;
            if (m == "all")
                o.textured_methods = {ltc::textured_method::fetch, ltc::textured_method::quick_cells,
                                      ltc::textured_method::exact_cells};
            else if (m == "fetch" || m == "quick_cells" || m == "exact_cells")
                o.textured_methods = {m == "fetch"         ? ltc::textured_method::fetch
                                      : m == "quick_cells" ? ltc::textured_method::quick_cells
                                                           : ltc::textured_method::exact_cells};
            else
                return option_status::bad;
        } else if (a == "--cells") {
            if (!v.integer_in(1, 1e7)) return option_status::bad;
            o.cells = static_cast<std::size_t>(v.number);
        } else if (a == "--lobes") {
            if (std::string(v.text) == "cosine") o.lobes = 3;
            else if (v.integer_in(1, 2)) o.lobes = static_cast<int>(v.number);
            else return option_status::bad;
        } else if (a == "--texture-radiance") {
            if (!v.is_number || !(v.number >= 0) || v.number > 1e6) return option_status::bad;
            o.texture_radiance = v.number;
        } else {
            return option_status::unknown;
        }
        return option_status::taken;
    };
    return ltc_examples::parse_command_line(argc, argv, o, print_help, flag, option);
}

}  // namespace render
