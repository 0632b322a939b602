// render/error_stats.hpp -- the LTC render against its reference: the relative error of luminance
// per floor pixel (error.png's false colour) and its statistics (mean, median, 95th percentile,
// max; per tile), next to the reference's own Monte Carlo noise.
#pragma once

#include "camera.hpp"
#include "common/colour.hpp"
#include "math.hpp"
#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace render {

/// Reference luminance (times the exposure) below which a pixel is left out of the statistics
/// and the relative error is taken against this floor instead: about 12/255 on screen.
constexpr double dark_floor = 0.01;

inline double percentile(std::vector<double> v, double p) {  // nearest rank
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t k = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size())));
    return v[std::min(v.size() - 1, k > 0 ? k - 1 : 0)];
}

inline double mean_of(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

inline bool finite3(const dvec3& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

/// Error statistics of an LTC image against its reference over the floor pixels.
struct error_stats {
    std::vector<double> rel, signed_rel, noise;
    std::size_t significant = 0, dark = 0;
    std::vector<std::vector<double>> tile_rel, tile_signed;
};

/// Relative error of luminance over the floor pixels with Y_ref >= floor; fills the false-colour
/// error image (count x 3 bytes; every floor pixel, against max(Y_ref, floor); the rest black).
inline error_stats measure_error(const std::vector<pixel_hit>& hits, const std::vector<dvec3>& ltc_img,
                                 const std::vector<dvec3>& ref_img, const std::vector<double>& ref_variance, double floor,
                                 std::vector<std::uint8_t>& rgb) {
    error_stats st;
    const std::size_t tiles = static_cast<std::size_t>(scene::columns) * scene::bands;
    st.tile_rel.resize(tiles);
    st.tile_signed.resize(tiles);
    for (std::size_t i = 0; i < hits.size(); ++i) {
        std::uint8_t* px = &rgb[3 * i];
        if (hits[i].kind != pixel_hit::floor) {
            px[0] = px[1] = px[2] = 0;
            continue;
        }
        const double y_ltc = luminance(ltc_img[i]), y_ref = luminance(ref_img[i]);
        const double e = std::abs(y_ltc - y_ref) / std::max(y_ref, floor);
        error_colour(e, px);
        if (!(y_ref >= floor)) {
            ++st.dark;
            continue;
        }
        const double se = std::sqrt(ref_variance[i]);
        st.rel.push_back(e);
        st.signed_rel.push_back((y_ltc - y_ref) / y_ref);
        st.noise.push_back(se / y_ref);
        st.significant += std::abs(y_ltc - y_ref) > 3 * se;
        const std::size_t m = static_cast<std::size_t>(hits[i].material);
        if (m < tiles) {
            st.tile_rel[m].push_back(e);
            st.tile_signed[m].push_back(st.signed_rel.back());
        }
    }
    return st;
}

inline void print_error(const scene& s, const error_stats& st, double floor, const char* y_ref = "Y_ref") {
    std::printf("relative error of the LTC render, |Y_ltc - Y_ref| / Y_ref of luminance, over the %zu floor pixels\n"
                "with %s >= %.3g (%zu darker floor pixels left out):\n",
                st.rel.size(), y_ref, floor, st.dark);
    std::printf("  mean %.2f%%  median %.2f%%  p95 %.2f%%  max %.2f%%  (mean signed %+.2f%%)\n", 100 * mean_of(st.rel),
                100 * percentile(st.rel, 0.5), 100 * percentile(st.rel, 0.95), 100 * percentile(st.rel, 1.0),
                100 * mean_of(st.signed_rel));
    std::printf("reference noise, relative standard error of Y_ref over the same pixels:\n");
    std::printf("  mean %.2f%%  median %.2f%%  p95 %.2f%%  max %.2f%%\n", 100 * mean_of(st.noise),
                100 * percentile(st.noise, 0.5), 100 * percentile(st.noise, 0.95), 100 * percentile(st.noise, 1.0));
    std::printf("pixels where |Y_ltc - Y_ref| > 3 standard errors (the LTC's error, not noise): %.1f%%\n",
                st.rel.empty() ? 0.0 : 100.0 * static_cast<double>(st.significant) / static_cast<double>(st.rel.size()));
    std::printf("\nper tile, mean |relative error| (mean signed); bands far to near, stripes left to right:\n");
    std::printf("  roughness");
    for (const char* name : s.column_names) std::printf(" %18s", name);
    std::printf("\n");
    for (int b = scene::bands - 1; b >= 0; --b) {
        std::printf("  %9.2f", static_cast<double>(s.roughness[b]));
        for (int c = 0; c < scene::columns; ++c) {
            const std::size_t m = static_cast<std::size_t>(b * scene::columns + c);
            if (st.tile_rel[m].empty()) {
                std::printf(" %18s", "-");
                continue;
            }
            char cell[40];
            std::snprintf(cell, sizeof cell, "%.1f%% (%+.1f%%)", 100 * mean_of(st.tile_rel[m]),
                          100 * mean_of(st.tile_signed[m]));
            std::printf(" %18s", cell);
        }
        std::printf("\n");
    }
}

}  // namespace render
