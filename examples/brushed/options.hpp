// brushed/options.hpp -- the command line: the options, their defaults, --help and the parser.
#pragma once

#include "common/cli.hpp"

#include <cstdio>
#include <string>

namespace brushed {

struct options : ltc_examples::image_options {  // --width, --height, --threads, --out, --seed, --exposure
    options() : image_options(192, 128) {}
    int samples = 1 << 12;  // --samples: Monte Carlo iterations per pixel
    float iso = 0.35f;                          // --iso-roughness
    float along = 0.15f, across = 0.6f;         // --brushed-along, --brushed-across
};

inline void print_help(const char* argv0) {
    std::printf(
        "usage: %s [--width W] [--height H] [--samples N] [--threads K] [--out DIR] [--exposure E]\n"
        "          [--seed S] [--iso-roughness R] [--brushed-along R] [--brushed-across R] [--help]\n"
        "\n"
        "Renders a metal floor under a one-sided quad light with anisotropic GGX, twice per material:\n"
        "with LTC (ltc::shade<ltc::ggx::anisotropic>) and with a Monte Carlo reference of the same\n"
        "BRDF (ltc::ground_truth::integrate of ltc::brdf::ggx_anisotropic). Materials: iso (by default\n"
        "roughness 0.35 both ways) and brushed (tangent +x: 0.15 along it, 0.6 across). Both are\n"
        "compared with F0 = 1 (the BRDF without Fresnel) and tinted by F0 = (0.95, 0.64, 0.54) for\n"
        "display only. Writes into DIR, for M = iso and brushed:\n"
        "  M_ltc.png        the LTC render\n"
        "  M_reference.png  the Monte Carlo reference\n"
        "  M_error.png      |ltc - ref| / max(ref, 0.01 / E) on a fixed scale: 0%% dark blue, 5%% blue,\n"
        "                   10%% green, 15%% yellow, 20%% and above red; the sky black\n"
        "It prints per material the times, the mean, 95th percentile and max of that error over\n"
        "the lit pixels (ref >= 0.01 / E) and over the highlight (ref >= 10%% of the peak; for iso\n"
        "also with ggx::one_lobe, the isotropic table), and the reference's relative standard error.\n"
        "\n"
        "  --width W        width of each image in pixels (default 192)\n"
        "  --height H       height of each image in pixels (default 128)\n"
        "  --samples N      Monte Carlo iterations per pixel (default 4096; each draws one BRDF and\n"
        "                   one light direction, balance heuristic)\n"
        "  --threads K      worker threads (default: all hardware threads); the images do not\n"
        "                   depend on it\n"
        "  --out DIR        output directory, created if needed (default: the current directory)\n"
        "  --exposure E     linear exposure before the tone curve (default 1)\n"
        "  --seed S         base seed of the reference (default 1)\n"
        "  --iso-roughness R   the iso material's roughness, in [0, 1] (default 0.35; alpha = R^2)\n"
        "  --brushed-along R   the brushed material's roughness along the tangent (default 0.15)\n"
        "  --brushed-across R  the brushed material's roughness across the tangent (default 0.6)\n"
        "  --help, -h       this text\n",
        argv0);
}

/// Returns 0 to go on, 1 after --help, 2 on an error (common/cli.hpp).
inline int parse_args(int argc, char** argv, options& o) {
    using ltc_examples::option_status;
    const auto no_flag = [](const std::string&) { return false; };
    const auto option = [&](const std::string& a, const ltc_examples::option_value& v) {
        float* roughness = a == "--iso-roughness"    ? &o.iso
                           : a == "--brushed-along"  ? &o.along
                           : a == "--brushed-across" ? &o.across
                                                     : nullptr;
        if (roughness != nullptr) {
            if (!v.is_number || !(v.number >= 0 && v.number <= 1)) return option_status::bad;
            *roughness = static_cast<float>(v.number);
        } else if (a == "--samples") {
            if (!v.integer_in(1, 1e8)) return option_status::bad;
            o.samples = static_cast<int>(v.number);
        } else {
            return option_status::unknown;
        }
        return option_status::taken;
    };
    return ltc_examples::parse_command_line(argc, argv, o, print_help, no_flag, option);
}

}  // namespace brushed
