// brushed -- anisotropic GGX on a metal floor: LTC beside Monte Carlo beside their error.
//
//   brushed [--width W] [--height H] [--samples N] [--threads K] [--out DIR] [--exposure E]
//           [--seed S] [--iso-roughness R] [--brushed-along R] [--brushed-across R] [--help]
//
// The scene (scene.hpp): the floor z = 0 seen by a pinhole camera 2.5 above it looking along +x,
// lit by one one-sided 1.0 x 1.2 quad light (radiance 4) above the view, facing the camera and
// tilted down; every floor point in view sees its front; no shadows. Two materials, the floor's
// tangent +x (the view direction):
//   iso      roughness --iso-roughness (0.35) along and across the tangent
//   brushed  roughness --brushed-along (0.15) along the tangent, --brushed-across (0.6) across
// Both are shaded by ltc::shade<ltc::ggx::anisotropic> (the 8^4 anisotropic table) with F0 = 1
// and no diffuse term, against L * ltc::ground_truth::integrate of ltc::brdf::ggx_anisotropic (no
// Fresnel), --samples MIS iterations per pixel, each pixel its own seed (the images do not depend
// on --threads). The comparison is of these F0 = 1 values; the images show them times F0 = (0.95,
// 0.64, 0.54), tone mapped alike (exposure, ACES filmic, sRGB).
//
// Images, written into --out (default: the current directory), for M = iso and brushed:
//   M_ltc.png, M_reference.png   the two renders
//   M_error.png   e = |ltc - ref| / max(ref, 0.01 / exposure), false colour (common/colour.hpp):
//                 0% dark blue, 5% blue, 10% green, 15% yellow, 20% and above red; sky black.
// Printed, per material: the times; the mean, p95 and max of e and the mean signed error over
// the lit pixels (ref >= 0.01 / exposure) and over the highlight (ref >= 10% of the image's
// peak); for iso the same for ggx::one_lobe (the 2D isotropic table) on the same pixels; the
// reference's relative standard error over the lit pixels (its own noise).
// Exit status 0, 1 if an image could not be written or a value was not finite, 2 for bad arguments.
//
// Source files: options.hpp (command line), scene.hpp (camera, light, rays), shade.hpp (one
// pixel, LTC and reference), this file (materials, renders, images, statistics).
#include "common/cli.hpp"
#include "common/colour.hpp"
#include "common/error_summary.hpp"
#include "common/image.hpp"
#include "common/random.hpp"
#include "common/threads.hpp"
#include "options.hpp"
#include "scene.hpp"
#include "shade.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace brushed;
using ltc_examples::clock_type;
using ltc_examples::seconds_since;

namespace {

/// Model's LTC value of every floor pixel (0 elsewhere), on `threads` workers.
template <typename Model>
std::vector<double> render_ltc(const std::vector<pixel_hit>& hits, const material& m, const quad_light& light,
                               int width, int height, unsigned threads) {
    std::vector<double> out(hits.size(), 0.0);
    ltc_examples::for_each_row(height, threads, [&](int y) {
        for (int x = 0; x < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            if (hits[i].floor) out[i] = shade_ltc<Model>(hits[i], m, light);
        }
    });
    return out;
}

/// (a - ref) / ref, or its absolute value, over the lit pixels (floor, ref >= floor).
std::vector<double> relative_errors(const std::vector<pixel_hit>& hits, const std::vector<double>& a,
                                    const std::vector<reference_value>& ref, double floor, bool signed_error = false) {
    std::vector<double> e;
    for (std::size_t i = 0; i < hits.size(); ++i)
        if (hits[i].floor && ref[i].radiance >= floor) {
            const double d = (a[i] - ref[i].radiance) / ref[i].radiance;
            e.push_back(signed_error ? d : std::abs(d));
        }
    return e;
}

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / double(v.size());
}

}  // namespace

int main(int argc, char** argv) {
    options opt;
    if (const int r = parse_args(argc, argv, opt); r != 0) return r == 1 ? 0 : 2;
    const int W = opt.width, H = opt.height;
    const std::size_t count = static_cast<std::size_t>(W) * H;
    const std::filesystem::path out_dir(opt.out);
    if (!ltc_examples::create_output_directory(out_dir)) return 1;

    const quad_light light;
    const std::vector<pixel_hit> hits = trace_camera(W, H);
    std::size_t floor_pixels = 0;
    for (const pixel_hit& h : hits) floor_pixels += h.floor;
    std::printf("%d x %d pixels per image (%zu on the floor), %d samples per pixel, %u thread%s\n", W, H,
                floor_pixels, opt.samples, opt.threads, opt.threads == 1 ? "" : "s");
    const double floor = 0.01 / opt.exposure;  // the error's floor, and what counts as lit
    bool ok = true;
    std::size_t nonfinite = 0;
    std::vector<std::uint8_t> rgb(count * 3);
    const auto tinted = [&](double value, std::uint8_t* out) {
        ltc_examples::tone_map(dvec3(metal_f0) * value, opt.exposure, out);
    };

    const material materials[2] = {{"iso", opt.iso, opt.iso}, {"brushed", opt.along, opt.across}};
    for (std::size_t k = 0; k < 2; ++k) {
        const material& m = materials[k];
        const std::string name = m.name;
        std::printf("\n%s: roughness %.3g along the tangent, %.3g across (alpha %.4g, %.4g)\n", m.name,
                    double(m.roughness), double(m.roughness_bitangent), double(m.roughness) * m.roughness,
                    double(m.roughness_bitangent) * m.roughness_bitangent);

        auto t0 = clock_type::now();
        std::vector<double> ltc_img = render_ltc<ltc::ggx::anisotropic>(hits, m, light, W, H, opt.threads);
        const double ltc_seconds = seconds_since(t0);

        std::vector<reference_value> ref(count);
        const std::uint64_t material_seed = ltc_examples::mix_seed(opt.seed, k);
        t0 = clock_type::now();
        ltc_examples::for_each_row(
            H, opt.threads,
            [&](int y) {
                for (int x = 0; x < W; ++x) {
                    const std::size_t i = static_cast<std::size_t>(y) * W + x;
                    if (hits[i].floor)
                        ref[i] = shade_reference(hits[i], m, light, opt.samples, ltc_examples::mix_seed(material_seed, i));
                }
            },
            ("reference " + name).c_str());
        const double ref_seconds = seconds_since(t0);

        for (std::size_t i = 0; i < count; ++i) {
            if (!std::isfinite(ltc_img[i])) ++nonfinite, ltc_img[i] = 0;
            if (!std::isfinite(ref[i].radiance) || !std::isfinite(ref[i].standard_error)) ++nonfinite, ref[i] = {};
        }

        // Images: the F0 = 1 values tinted alike; the sky black.
        for (std::size_t i = 0; i < count; ++i) tinted(ltc_img[i], &rgb[3 * i]);
        ok = ltc_examples::write_png(out_dir / (name + "_ltc.png"), W, H, rgb) && ok;
        for (std::size_t i = 0; i < count; ++i) tinted(ref[i].radiance, &rgb[3 * i]);
        ok = ltc_examples::write_png(out_dir / (name + "_reference.png"), W, H, rgb) && ok;
        for (std::size_t i = 0; i < count; ++i) {
            const double e = std::abs(ltc_img[i] - ref[i].radiance) / std::max(ref[i].radiance, floor);
            if (hits[i].floor)
                ltc_examples::error_colour(e, &rgb[3 * i]);
            else
                rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = 0;
        }
        ok = ltc_examples::write_png(out_dir / (name + "_error.png"), W, H, rgb) && ok;

        // Statistics over the lit pixels, and over the highlight alone (ref >= 10% of the peak):
        // the LTC's relative error grows in the lobe's tails, where the radiance is small.
        double peak = 0;
        for (const reference_value& r : ref) peak = std::max(peak, r.radiance);
        std::printf("  times: LTC %.3f s, reference %.1f s\n", ltc_seconds, ref_seconds);
        std::printf("  reference peak %.3f; lit pixels (ref >= %g) %zu, highlight (ref >= %.3f) %zu\n", peak, floor,
                    relative_errors(hits, ltc_img, ref, floor).size(), 0.1 * peak,
                    relative_errors(hits, ltc_img, ref, 0.1 * peak).size());
        const auto report = [&](const char* label, const std::vector<double>& img) {
            for (const double f : {floor, 0.1 * peak}) {
                const ltc_examples::stats s = ltc_examples::summarize(relative_errors(hits, img, ref, f));
                std::printf("  %-17s %-9s |ltc - ref| / ref: mean %6.2f%%, p95 %6.2f%%, max %7.1f%%; mean signed %+.2f%%\n",
                            label, f == floor ? "lit" : "highlight", 100 * s.mean, 100 * s.p95, 100 * s.max,
                            100 * mean(relative_errors(hits, img, ref, f, true)));
            }
        };
        report("ggx::anisotropic", ltc_img);
        if (m.roughness == m.roughness_bitangent)  // the 2D isotropic table on the same pixels
            report("ggx::one_lobe", render_ltc<ltc::ggx::one_lobe>(hits, m, light, W, H, opt.threads));
        std::vector<double> noise;
        for (std::size_t i = 0; i < count; ++i)
            if (hits[i].floor && ref[i].radiance >= floor)
                noise.push_back(ref[i].standard_error / ref[i].radiance);
        const ltc_examples::stats n = ltc_examples::summarize(noise);
        std::printf("  reference noise (relative standard error, lit): mean %.2f%%, p95 %.2f%%, max %.1f%%\n",
                    100 * n.mean, 100 * n.p95, 100 * n.max);
    }
    std::printf("\nnon-finite values: %zu\n", nonfinite);
    return ok && nonfinite == 0 ? 0 : 1;
}
