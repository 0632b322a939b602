// shadows/denoise.hpp -- methods (d) and (e): a cross-bilateral filter over the image, applied
//   (d)  to (a)'s two Monte Carlo estimates per term (ltc::ratio_estimates: the sums of f V / p
//        and f / p over the same samples), each filtered on its own, the pixel's analytic terms
//        times the ratio of the filtered sums (ltc::ratio_shading). This is how Heitz, Hill and
//        McGuire (I3D 2018) denoise: the filter blurs the visibility only; the analytic shading,
//        its highlights and its tile edges stay sharp, and where no neighbour is shadowed the
//        sums are the same and the ratio is exactly 1;
//   (e)  to (c)'s radiance, with the same weights: the same filter on plain Monte Carlo, for a
//        fair comparison; it blurs the shading too.
// The filter: separable (rows, then columns: (2R + 1) taps each instead of (2R + 1)^2), Gaussian
// in pixels (sigma = R / 2), each tap kept only on the same surface as the centre pixel: the same
// kind (floor or occluder) and material, normals within 18 degrees, and the tap's point within
// 1% of the centre's distance from its tangent plane. Neither pass crosses an edge between tiles
// of different materials (tiles of one material meet at corners only), the box's edges or the
// silhouettes. Cost: about 2 (2R + 1) taps of 4 (d) or 3 (e) values per
// shaded pixel, timed with the shading (measure.hpp).
#pragma once

#include "camera.hpp"
#include "common/threads.hpp"
#include "scene.hpp"
#include "shade_mis.hpp"  // shaded_pixel

#include <ltc/shading/shadowed_polygon_light.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace shadows {

/// What the filter compares of two pixels: the hit, and the distance from the centre's tangent
/// plane that a tap may have (1% of the centre's distance from the eye).
struct filter_pixel {
    const pixel_hit* hit;
    float plane_tolerance;
};

inline std::vector<filter_pixel> filter_pixels(const std::vector<pixel_hit>& hits, const vec3& eye) {
    std::vector<filter_pixel> f(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i) f[i] = {&hits[i], 0.01f * glm::length(hits[i].p - eye)};
    return f;
}

/// Whether the tap b lies on the surface of the centre pixel a (file comment).
inline bool same_surface(const filter_pixel& a, const pixel_hit& b) {
    const pixel_hit& h = *a.hit;
    if (h.kind != b.kind || h.material != b.material || !h.shaded()) return false;
    if (glm::dot(h.n, b.n) < 0.95f) return false;
    return std::abs(glm::dot(h.n, b.p - h.p)) <= a.plane_tolerance;
}

/// One pass of the separable filter along x (dx = 1) or y: out[i] = sum_j w_ij in[j] / sum_j w_ij
/// over the taps j on i's surface (the centre always is).
template <std::size_t N>
void filter_pass(const std::vector<filter_pixel>& pixels, int W, int H, int radius, bool along_x,
                 unsigned threads, const std::vector<std::array<double, N>>& in,
                 std::vector<std::array<double, N>>& out) {
    std::vector<double> g(static_cast<std::size_t>(radius) + 1);
    const double sigma = 0.5 * radius;
    for (int k = 0; k <= radius; ++k) g[static_cast<std::size_t>(k)] = std::exp(-0.5 * k * k / (sigma * sigma));
    ltc_examples::for_each_row(H, threads, [&](int y) {
        for (int x = 0; x < W; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * W + x;
            out[i] = in[i];
            if (!pixels[i].hit->shaded()) continue;
            std::array<double, N> sum{};
            double weight = 0;
            for (int k = -radius; k <= radius; ++k) {
                const int xx = along_x ? x + k : x, yy = along_x ? y : y + k;
                if (xx < 0 || xx >= W || yy < 0 || yy >= H) continue;
                const std::size_t j = static_cast<std::size_t>(yy) * W + xx;
                if (j != i && !same_surface(pixels[i], *pixels[j].hit)) continue;
                const double w = g[static_cast<std::size_t>(std::abs(k))];
                weight += w;
                for (std::size_t c = 0; c < N; ++c) sum[c] += w * in[j][c];
            }
            for (std::size_t c = 0; c < N; ++c) out[i][c] = sum[c] / weight;
        }
    });
}

/// The filter (rows, then columns) of N values per pixel.
template <std::size_t N>
std::vector<std::array<double, N>> cross_bilateral(const std::vector<pixel_hit>& hits, const vec3& eye, int W, int H,
                                                   int radius, unsigned threads, std::vector<std::array<double, N>> v) {
    if (radius <= 0) return v;
    const std::vector<filter_pixel> pixels = filter_pixels(hits, eye);
    std::vector<std::array<double, N>> rows(v.size());
    filter_pass(pixels, W, H, radius, true, threads, v, rows);
    filter_pass(pixels, W, H, radius, false, threads, rows, v);
    return v;
}

/// (d): each pixel's radiance from its analytic terms and the filtered estimates (file comment).
inline void denoise_ratio(const std::vector<pixel_hit>& hits, const vec3& eye, int W, int H, int radius,
                          unsigned threads, std::vector<shaded_pixel>& px) {
    std::vector<std::array<double, 4>> v(px.size());
    for (std::size_t i = 0; i < px.size(); ++i)
        v[i] = {px[i].specular_estimates.visible, px[i].specular_estimates.total,
                px[i].diffuse_estimates.visible, px[i].diffuse_estimates.total};
    v = cross_bilateral(hits, eye, W, H, radius, threads, std::move(v));
    for (std::size_t i = 0; i < px.size(); ++i) {
        if (!hits[i].shaded()) continue;
        const ltc::ratio_estimates<double> s{v[i][0], v[i][1]}, d{v[i][2], v[i][3]};
        px[i].radiance = ltc::ratio_shading(px[i].specular, s) + ltc::ratio_shading(px[i].diffuse, d);
    }
}

/// (e): each pixel's radiance filtered.
inline void denoise_radiance(const std::vector<pixel_hit>& hits, const vec3& eye, int W, int H, int radius,
                             unsigned threads, std::vector<shaded_pixel>& px) {
    std::vector<std::array<double, 3>> v(px.size());
    for (std::size_t i = 0; i < px.size(); ++i) v[i] = {px[i].radiance.r, px[i].radiance.g, px[i].radiance.b};
    v = cross_bilateral(hits, eye, W, H, radius, threads, std::move(v));
    for (std::size_t i = 0; i < px.size(); ++i)
        if (hits[i].shaded()) px[i].radiance = dvec3(v[i][0], v[i][1], v[i][2]);
}

}  // namespace shadows
