// render/report.hpp -- the error images and the printed statistics of the LTC render against the
// reference: error.png and the statistics of all lights; with the textured light also those of
// the polygonal lights alone and of the textured light alone (textured_error.png), and with
// --textured-method all those of each method (textured_error_<method>.png), then the methods
// side by side. With --lobes 1 or 2 the headings say that the polygonal lights have one or two lobes.
#pragma once

#include "camera.hpp"
#include "common/image.hpp"
#include "error_stats.hpp"
#include "math.hpp"
#include "options.hpp"
#include "reference_render.hpp"
#include "scene.hpp"
#include "textured_methods.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace render {

/// Writes the error images into out_dir and prints the statistics; ltc_poly is the polygonal
/// lights' LTC render, ltc_img that of ltc.png (with the first run's textured light), rgb a
/// count x 3 byte buffer. Returns whether every image was written.
inline bool report_errors(const scene& s, const std::vector<pixel_hit>& hits, const std::vector<dvec3>& ltc_poly,
                          const std::vector<dvec3>& ltc_img, const std::vector<textured_run>& runs,
                          const reference_render& ref, const std::string& method_note, std::size_t floor_pixels,
                          const options& opt, const std::filesystem::path& out_dir, std::vector<std::uint8_t>& rgb) {
    const int W = opt.width, H = opt.height;
    const bool compare = runs.size() > 1;  // --textured-method all
    const double floor = dark_floor / opt.exposure;
    const error_stats all = measure_error(hits, ltc_img, ref.img, ref.var_all, floor, rgb);
    bool ok = write_png(out_dir / "error.png", W, H, rgb);
    if (!s.textured) {
        std::printf("\n");
        print_error(s, all, floor);
        return ok;
    }
    // The textured light alone, by each method, against the one reference.
    std::vector<error_stats> tex_stats;
    for (const textured_run& r : runs) {
        tex_stats.push_back(measure_error(hits, r.ltc, ref.tex, ref.var_tex, floor, rgb));
        if (tex_stats.size() == 1) ok = write_png(out_dir / "textured_error.png", W, H, rgb) && ok;
        if (compare)
            ok = write_png(out_dir / ("textured_error_" + std::string(method_name(r.policy.method)) + ".png"), W, H,
                           rgb) &&
                 ok;
    }
    const error_stats poly_stats = measure_error(hits, ltc_poly, ref.poly, ref.var_poly, floor, rgb);
    std::printf("\n=== all lights (ltc.png, reference.png, error.png%s%s%s%s) ===\n",
                opt.lobes == 3 ? "" : "; the polygonal lights", lobes_note(opt.lobes),
                method_note.empty() ? "" : "; the textured light", method_note.c_str());
    print_error(s, all, floor);
    std::printf("\n=== the polygonal lights alone%s (rectangle + pentagon: the statistics of --no-texture%s) ===\n",
                lobes_note(opt.lobes), lobes_option(opt.lobes));
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
    return ok;
}

}  // namespace render
