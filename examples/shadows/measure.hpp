// shadows/measure.hpp -- a method's image, timed, and its error against the reference.
//
// Time: wall clock of shading the whole image (every pixel, the given worker threads; the camera
// rays, traced once before, excluded), and for (d) and (e) of their filter (denoise.hpp). Each
// render runs twice, and again until 0.5 s have passed (at most 5 times), with the same seeds
// (the same image), and the best time is kept: so that milliseconds are not swamped by thread
// start-up, and other processes' brief use of the cores is filtered out. Next to it, the
// process's CPU time (std::clock, all threads; best of the same runs): on a machine shared with
// other work, where the wall clock of a 2-thread render depends on who else runs, the CPU time of
// the same work barely does.
// Error of luminance Y (Rec. 709) against the reference, over a region: all the floor pixels, or
// those of its dielectric or of its gold tiles:
//   e = (Y - Y_ref) / max(Y_ref, floor),  floor = 0.01 / exposure (about 12/255 on screen: the
//   umbrae, where Y_ref = 0, count as absolute errors against that floor instead of dividing by 0)
//   mean relative error  = mean |e|,   relative RMSE = sqrt(mean e^2)
// The error images show |e| on the fixed scale of render's error.png (0% dark blue, 5% blue, 10%
// green, 15% yellow, 20% and above red); all but floor and occluder pixels are black.
#pragma once

#include "camera.hpp"
#include "common/colour.hpp"
#include "common/threads.hpp"
#include "denoise.hpp"
#include "scene.hpp"
#include "shade_ratio.hpp"
#include "tracer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <ctime>
#include <vector>

namespace shadows {

struct method_image {
    std::vector<dvec3> img;
    std::vector<double> luminance_variance;  // the estimate's, per pixel (MIS only; else 0)
    double seconds = 0;      // wall clock
    double cpu_seconds = 0;  // CPU time of all threads
    double rays_per_pixel = 0;  // visibility queries per shaded (floor or occluder) pixel
    std::size_t nonfinite = 0;  // pixels with a non-finite value (expected 0), made black
};

/// Every pixel by `which` at `spp`, seeded by (seed, which, spp, pixel), the ratio methods' analytic
/// part with `lobes`, (d)'s and (e)'s filter as `filter` sets it (its radius -1: auto_radius(spp);
/// denoise.hpp), the pixels'
/// sample points screen-ordered with screen_points (screen_order.hpp); timed with the
/// filter (file comment) over up to max_runs runs (1: the reference, the second seeds). With a
/// label: its progress on stderr.
inline method_image render_method(const scene& s, const tracer& tr, const std::vector<pixel_hit>& hits, int W, int H,
                                  unsigned threads, method which, int spp, std::uint64_t seed, analytic_model lobes,
                                  const filter_settings& filter, bool screen_points, int max_runs = 5,
                                  const char* label = nullptr) {
    const std::size_t count = static_cast<std::size_t>(W) * H;
    // (a+) draws (a)'s random numbers (common random numbers: where K <= K0 its first call is (a)'s
    // call), so that the difference of the two measures its early stop with little noise.
    // (d) and (e) filter (a)'s and (c)'s images: the same random numbers, so that the difference
    // shows the filter's effect alone ((e) with --pixel-points random: by default its points are
    // screen-ordered and (c)'s are not, since without a filter the ordering only costs time).
    const method seeded_as = which == method::ratio_ltc_adaptive || which == method::ratio_ltc_denoised ? method::ratio_ltc
                             : which == method::mis_denoised                                          ? method::mis
                                                                                                      : which;
    const int radius = filter.radius >= 0 ? filter.radius : auto_radius(spp);
    const bool penumbra = filter.penumbra_at(radius);  // (d) records its blockers for penumbra_radii
    const std::uint64_t run =
        mix_seed(mix_seed(seed, static_cast<std::uint64_t>(seeded_as)), static_cast<std::uint64_t>(spp));
    const ltc::polygon_light<float> light = ltc_light(s);  // once, for every pixel and run
    std::vector<shaded_pixel> px(count);
    method_image r;
    r.seconds = r.cpu_seconds = 1e300;
    double total = 0;
    for (int repeat = 0; repeat < max_runs && (repeat < 2 || total < 0.5); ++repeat) {
        const auto t0 = ltc_examples::clock_type::now();
        const std::clock_t c0 = std::clock();
        ltc_examples::for_each_row(
            H, threads,
            [&](int y) {
                for (int x = 0; x < W; ++x) {
                    const std::size_t i = static_cast<std::size_t>(y) * W + x;
                    const pixel_points points{screen_points && which != method::mis, x, y, mix_seed(run, 0x5C2EE7u)};
                    px[i] = shade(s, light, tr, hits[i], which, spp, mix_seed(run, i), lobes, points, penumbra);
                }
            },
            label);
        if (which == method::ratio_ltc_denoised)
            denoise_ratio(hits, s, W, H, radius, filter, threads, px);
        if (which == method::mis_denoised) denoise_radiance(hits, s, W, H, radius, threads, px);
        const double t = ltc_examples::seconds_since(t0);
        r.cpu_seconds = std::min(r.cpu_seconds, static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
        r.seconds = std::min(r.seconds, t);
        total += t;
    }
    r.img.resize(count);
    r.luminance_variance.resize(count);
    std::size_t shaded = 0, rays = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const bool finite = std::isfinite(px[i].radiance.r) && std::isfinite(px[i].radiance.g) &&
                            std::isfinite(px[i].radiance.b) && std::isfinite(px[i].luminance_variance);
        r.nonfinite += !finite;
        r.img[i] = finite ? px[i].radiance : dvec3(0.0);
        r.luminance_variance[i] = finite ? px[i].luminance_variance : 0.0;
        shaded += hits[i].shaded();
        rays += px[i].rays;
    }
    r.rays_per_pixel = shaded > 0 ? static_cast<double>(rays) / static_cast<double>(shaded) : 0.0;
    return r;
}

/// The floor pixels an error is taken over: all of them, or its dielectric or its gold tiles.
enum class region { floor, dielectric, gold };
constexpr region regions[] = {region::floor, region::dielectric, region::gold};

inline const char* region_name(region g) {
    return g == region::floor ? "all the floor" : g == region::dielectric ? "the dielectric tiles" : "the gold tiles";
}

inline bool in_region(const pixel_hit& h, region g) {
    return h.kind == pixel_hit::floor && (g == region::floor || (g == region::gold) == scene::is_gold(h.material));
}

struct error_measure {
    double mean_rel = 0, rel_rmse = 0, mean_signed = 0;
    std::size_t pixels = 0;
};

/// An error_measure per region.
struct region_errors {
    std::array<error_measure, std::size(regions)> of;
    error_measure& operator[](region g) { return of[static_cast<std::size_t>(g)]; }
    const error_measure& operator[](region g) const { return of[static_cast<std::size_t>(g)]; }
};

inline double relative_error(const dvec3& x, const dvec3& ref, double floor) {
    const double y_ref = ltc_examples::luminance(ref);
    return (ltc_examples::luminance(x) - y_ref) / std::max(y_ref, floor);
}

/// The errors of img over each region; with rgb (count x 3 bytes), the error image.
inline region_errors measure_error(const std::vector<pixel_hit>& hits, const std::vector<dvec3>& img,
                                   const std::vector<dvec3>& ref, double floor,
                                   std::vector<std::uint8_t>* rgb = nullptr) {
    region_errors m;
    std::array<double, std::size(regions)> sum2{};
    for (std::size_t i = 0; i < hits.size(); ++i) {
        const double e = hits[i].shaded() ? relative_error(img[i], ref[i], floor) : 0.0;
        if (rgb != nullptr) {
            std::uint8_t* p = &(*rgb)[3 * i];
            if (hits[i].shaded())
                ltc_examples::error_colour(std::abs(e), p);
            else
                p[0] = p[1] = p[2] = 0;
        }
        for (region g : regions) {
            if (!in_region(hits[i], g)) continue;
            error_measure& r = m[g];
            ++r.pixels;
            r.mean_rel += std::abs(e);
            r.mean_signed += e;
            sum2[static_cast<std::size_t>(g)] += e * e;
        }
    }
    for (region g : regions) {
        error_measure& r = m[g];
        if (r.pixels == 0) continue;
        const double n = static_cast<double>(r.pixels);
        r.mean_rel /= n, r.mean_signed /= n, r.rel_rmse = std::sqrt(sum2[static_cast<std::size_t>(g)] / n);
    }
    return m;
}

/// Relative noise of two renders with independent seeds, over the floor pixels: the RMS over
/// pixels of the per-pixel standard deviation estimated from the pair, |x1 - x2| / sqrt(2),
/// relative to max(Y_ref, floor) (unbiased for the mean variance).
inline double relative_noise(const std::vector<pixel_hit>& hits, const std::vector<dvec3>& a,
                             const std::vector<dvec3>& b, const std::vector<dvec3>& ref, double floor) {
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < hits.size(); ++i) {
        if (hits[i].kind != pixel_hit::floor) continue;
        const double y_ref = std::max(ltc_examples::luminance(ref[i]), floor);
        const double d = (ltc_examples::luminance(a[i]) - ltc_examples::luminance(b[i])) / y_ref;
        sum += 0.5 * d * d;
        ++n;
    }
    return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

/// How far the expectation of one method lies from another's, over the floor pixels, from two
/// renders of each with independent seeds (a1, b1 with the first, a2, b2 with the second; a and b
/// may share random numbers): d_s = (Y(a_s) - Y(b_s)) / max(Y_ref, floor) per pixel and seed;
/// rms = sqrt(mean of d_1 d_2), each product an unbiased estimate of the squared difference of
/// the expectations (0 if the mean is negative), and the mean of (d_1 + d_2) / 2.
struct shift_measure {
    double rms = 0, mean_signed = 0;
};

inline shift_measure relative_shift(const std::vector<pixel_hit>& hits, const std::vector<dvec3>& a1,
                                    const std::vector<dvec3>& a2, const std::vector<dvec3>& b1,
                                    const std::vector<dvec3>& b2, const std::vector<dvec3>& ref, double floor) {
    using ltc_examples::luminance;
    shift_measure m;
    double product = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < hits.size(); ++i) {
        if (hits[i].kind != pixel_hit::floor) continue;
        const double y_ref = std::max(luminance(ref[i]), floor);
        const double d1 = (luminance(a1[i]) - luminance(b1[i])) / y_ref;
        const double d2 = (luminance(a2[i]) - luminance(b2[i])) / y_ref;
        product += d1 * d2;
        m.mean_signed += 0.5 * (d1 + d2);
        ++n;
    }
    if (n == 0) return m;
    m.mean_signed /= static_cast<double>(n);
    m.rms = std::sqrt(std::max(0.0, product / static_cast<double>(n)));
    return m;
}

/// The reference's own noise over the floor pixels: its standard error relative to
/// max(Y_ref, floor), mean and RMS.
struct noise_measure {
    double mean = 0, rms = 0;
};

inline noise_measure reference_noise(const std::vector<pixel_hit>& hits, const method_image& ref, double floor) {
    noise_measure m;
    std::size_t n = 0;
    for (std::size_t i = 0; i < hits.size(); ++i) {
        if (hits[i].kind != pixel_hit::floor) continue;
        const double y = std::max(ltc_examples::luminance(ref.img[i]), floor);
        m.mean += std::sqrt(ref.luminance_variance[i]) / y;
        m.rms += ref.luminance_variance[i] / (y * y);
        ++n;
    }
    if (n > 0) m.mean /= static_cast<double>(n), m.rms = std::sqrt(m.rms / static_cast<double>(n));
    return m;
}

}  // namespace shadows
