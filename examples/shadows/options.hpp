// shadows/options.hpp -- the command line: the options, their defaults, --help and the parser
// (the options and loop it shares with render: common/cli.hpp).
#pragma once

#include "common/cli.hpp"
#include "filter_settings.hpp"

#include "shade_ratio.hpp"  // analytic_model

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace shadows {

struct options : ltc_examples::image_options {  // --width, --height, --threads, --out, --seed, --exposure
    options() : image_options(320, 200) {}
    std::vector<int> spp{1, 2, 4, 8, 16, 32, 64};                 // (a): K, visibility queries in all
    std::vector<int> adaptive_spp{1, 2, 4, 8, 16, 32, 64};        // (a+): K (after K0 = min(K, 4))
    std::vector<int> area_spp{1, 2, 4, 8, 16, 32, 64, 128, 256};  // (b): K (cheaper: a longer sweep)
    std::vector<int> mis_spp{1, 2, 4, 8, 16, 32, 64, 128, 256};   // (c): iterations
    std::vector<int> denoised_spp{1, 2, 4, 8, 16, 32, 64};        // (d): K
    std::vector<int> denoised_mis_spp{1, 2, 4, 8, 16, 32, 64, 128, 256};  // (e): iterations
    // (d) and (e): the filter's half-width in pixels (-1: auto_radius(K)); (d): the specular term's
    // LTC error corrected too (ltc::corrected_specular), and each pixel's radius from the
    // penumbra's width (filter_settings.hpp)
    filter_settings filter;
    bool screen_points = true;   // every method but (c) and the reference: screen-ordered points (screen_order.hpp)
    int reference_spp = 4096;  // (c)'s iterations for the reference
    analytic_model lobes = analytic_model::one_lobe;  // (a), (a+), (b), (d): the analytic part's model
};

inline void print_help(const char* argv0) {
    std::printf(
        "usage: %s [--width W] [--height H] [--spp LIST] [--adaptive-spp LIST] [--area-spp LIST]\n"
        "          [--mis-spp LIST] [--denoised-spp LIST] [--denoised-mis-spp LIST]\n"
        "          [--denoise-radius R|auto] [--filter-radius penumbra|fixed] [--ltc-correction on|off]\n"
        "          [--pixel-points screen|random]\n"
        "          [--reference-spp N] [--threads K]\n"
        "          [--out DIR] [--seed S] [--exposure E] [--lobes 1|2|cosine] [--help]\n"
        "\n"
        "Renders a tiled GGX floor (dielectric and gold tiles) and two grey occluders lit by one quad\n"
        "light, with shadows traced by Embree, six ways: (a) LTC + ratio-estimator shadows\n"
        "(ltc::shade_shadowed), K samples in all split between the LTC restricted to\n"
        "the light and the light's area, MIS-combined; (a+) the same, stopping after K0 = min(K, 4) samples\n"
        "where they all agree (lit or in umbra), else K more; (b) the same ratio sampling the light's\n"
        "area; (c) plain Monte Carlo with MIS (one GGX-or-cosine and one light sample per\n"
        "iteration); (d) (a) with its estimates per term denoised by a cross-bilateral filter\n"
        "(Heitz et al. 2018's denoising: the shadows blurred, not the shading), by default its\n"
        "specular term also corrected for the LTC's fitting error by the same samples; (e) (c) with the\n"
        "same filter on its radiance. The reference is (c) at --reference-spp. Writes into DIR:\n"
        "reference.png; M_Nspp.png for each method M (ratio_ltc, ratio_ltc_adaptive, ratio_area,\n"
        "mis, ratio_ltc_denoised, mis_denoised) and N = 1, 4, 16 (those in the lists);\n"
        "error_M_4spp.png (relative error of luminance, 0%% dark blue .. 20%%+ red);\n"
        "error_vs_time.csv (every method and spp: shading seconds, errors over all the floor, its\n"
        "dielectric and its gold tiles; plot_error_vs_time.py draws it). Prints the tables (all\n"
        "floor, dielectric, gold), the equal-time error ratios and the noise and bias of (a), (a+)\n"
        "and (d).\n"
        "\n"
        "  --width W           image width (default 320)\n"
        "  --height H          image height (default 200)\n"
        "  --spp LIST          K of (a), shadow rays in all: comma-separated (default 1,2,4,...,64)\n"
        "  --adaptive-spp LIST K of (a+): K0 = min(K, 4) rays, K0 + K where the first disagree\n"
        "                      (default 1,2,4,...,64)\n"
        "  --area-spp LIST     K of (b), up to K rays (default 1,2,4,...,256)\n"
        "  --mis-spp LIST      iterations of (c), up to 2 rays each (default 1,2,4,...,256)\n"
        "  --denoised-spp LIST K of (d) (default 1,2,4,...,64)\n"
        "  --denoised-mis-spp LIST\n"
        "                      iterations of (e) (default 1,2,4,...,256)\n"
        "  --denoise-radius R|auto\n"
        "                      (d)'s and (e)'s filter: 2 R + 1 taps per pass, 0 none; auto (the\n"
        "                      default): R = 4 (K / 4)^(-1/6) rounded, K the samples or iterations\n"
        "                      (5 at K = 1, 4 at 2-8, 3 at 16-64, 2 at 128-256)\n"
        "  --filter-radius penumbra|fixed\n"
        "                      (d)'s radius per pixel: by default about half the penumbra's width\n"
        "                      there (in pixels), in [1, R], from the blocker distances of the occluded\n"
        "                      shadow rays of the pixel and its neighbours (percentage-closer soft\n"
        "                      shadows' estimate), so that hard shadow edges stay sharp; or R everywhere\n"
        "  --ltc-correction on|off\n"
        "                      (d)'s specular term: the pixel's analytic values times the filtered\n"
        "                      Monte Carlo estimates of the shadowed integrals relative to theirs,\n"
        "                      which corrects the LTC's fitting error too (ltc::corrected_specular;\n"
        "                      default on), or off: the analytic term times the ratio of the\n"
        "                      filtered sums (ltc::ratio_shading, Heitz et al. 2018)\n"
        "  --pixel-points screen|random\n"
        "                      each pixel's sample points (the lattice rotation of (a), (a+)'s first\n"
        "                      call, (b) and (d); each iteration's points of (e)): by default\n"
        "                      screen-ordered, the neighbours' points stratified together (scrambled\n"
        "                      Sobol points in a shuffled Morton order of the pixels:\n"
        "                      ltc/core/screen_order.hpp), or independent random numbers per pixel;\n"
        "                      (c)'s and the reference's are random\n"
        "  --reference-spp N   iterations of the reference (default 4096)\n"
        "  --lobes 1|2|cosine  the ratio methods' analytic, unshadowed part from the one-lobe GGX table\n"
        "                      (default: ltc::ggx::one_lobe), the two-lobe table\n"
        "                      (ltc::ggx::two_lobes) or the table of an LTC and the cosine\n"
        "                      (ltc::ggx::ltc_and_cosine, ltc::shade's default); the samples of\n"
        "                      (a), (a+) and (d) follow that table's first, or only, LTC; (c), (e) and\n"
        "                      the reference do not change\n"
        "  --threads K         worker threads (default: all hardware threads); the images do not\n"
        "                      depend on it, the times do\n"
        "  --out DIR           output directory, created if needed (default: the current directory)\n"
        "  --seed S            base seed (default 1)\n"
        "  --exposure E        linear exposure before the tone curve (default 1)\n"
        "  --help, -h          this text\n"
        "\n"
        "The default run takes about 40 s on 2 idle cores (75 s of CPU time).\n",
        argv0);
}

/// "1,4,16" -> {1, 4, 16}: positive integers up to `max`, sorted, without repeats.
inline bool parse_list(const std::string& s, int max, std::vector<int>& out) {
    out.clear();
    std::size_t start = 0;
    while (start <= s.size()) {
        const std::size_t comma = std::min(s.find(',', start), s.size());
        double v = 0;
        const std::string item = s.substr(start, comma - start);
        if (!ltc_examples::parse_number(item.c_str(), v) || v != std::floor(v) || v < 1 || v > max) return false;
        out.push_back(static_cast<int>(v));
        start = comma + 1;
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return !out.empty();
}

/// Returns 0 to go on, 1 after --help, 2 on an error (common/cli.hpp).
inline int parse_args(int argc, char** argv, options& o) {
    using ltc_examples::option_status;
    const auto no_flags = [](const std::string&) { return false; };
    const auto option = [&](const std::string& a, const ltc_examples::option_value& v) {
        std::vector<int>* list = a == "--spp"            ? &o.spp
                                 : a == "--adaptive-spp" ? &o.adaptive_spp
                                 : a == "--area-spp"     ? &o.area_spp
                                 : a == "--mis-spp"      ? &o.mis_spp
                                 : a == "--denoised-spp" ? &o.denoised_spp
                                 : a == "--denoised-mis-spp" ? &o.denoised_mis_spp
                                                         : nullptr;
        if (list != nullptr) return parse_list(v.text, 1 << 20, *list) ? option_status::taken : option_status::bad;
        if (a == "--lobes") {
            if (std::string(v.text) == "cosine")
                o.lobes = analytic_model::ltc_and_cosine;
            else if (v.integer_in(1, 2))
                o.lobes = v.number == 2 ? analytic_model::two_lobes : analytic_model::one_lobe;
            else
                return option_status::bad;
            return option_status::taken;
        }
        if (a == "--ltc-correction") {
            const std::string t(v.text);
            if (t != "on" && t != "off") return option_status::bad;
            o.filter.ltc_correction = t == "on";
            return option_status::taken;
        }
        if (a == "--filter-radius") {
            const std::string t(v.text);
            if (t != "penumbra" && t != "fixed") return option_status::bad;
            o.filter.penumbra = t == "penumbra";
            return option_status::taken;
        }
        if (a == "--pixel-points") {
            const std::string t(v.text);
            if (t != "screen" && t != "random") return option_status::bad;
            o.screen_points = t == "screen";
            return option_status::taken;
        }
        if (a == "--denoise-radius") {
            if (std::string(v.text) == "auto") {
                o.filter.radius = -1;
                return option_status::taken;
            }
            if (!v.integer_in(0, 64)) return option_status::bad;
            o.filter.radius = static_cast<int>(v.number);
            return option_status::taken;
        }
        if (a != "--reference-spp") return option_status::unknown;
        if (!v.integer_in(1, 1e8)) return option_status::bad;
        o.reference_spp = static_cast<int>(v.number);
        return option_status::taken;
    };
    return ltc_examples::parse_command_line(argc, argv, o, print_help, no_flags, option);
}

}  // namespace shadows
