// shadows/denoise.hpp -- methods (d) and (e): a cross-bilateral filter over the image, applied
//   (d)  to (a)'s two Monte Carlo estimates per term (ltc::ratio_estimates: the sums of f V / p
//        and f / p over the same samples), each filtered on its own, the pixel's analytic terms
//        times the ratio of the filtered sums (ltc::ratio_shading). This is how Heitz, Hill and
//        McGuire (I3D 2018) denoise: the filter blurs the visibility only; the analytic shading,
//        its highlights and its tile edges stay sharp, and where no neighbour is shadowed the
//        sums are the same and the ratio is exactly 1. The sums' f carries no albedo and no
//        Fresnel term, so they are shared across materials: the diffuse sums (f = cos / pi) over
//        the whole surface, the specular ones (GGX) between tiles of the same roughness; but not
//        between materials with and without a diffuse term (same_surface: their sample plans
//        differ);
//   (e)  to (c)'s radiance, with the same weights, its taps of the centre's material only (the
//        radiance carries the albedo and the Fresnel term): the same filter on plain Monte
//        Carlo, for a fair comparison; it blurs the shading too.
// The filter: separable (rows, then columns: (2R + 1) taps each instead of (2R + 1)^2), Gaussian
// in pixels (sigma = R / 2), each tap kept only on the same surface as the centre pixel: the same
// kind (floor or occluder), normals within 18 degrees, and the tap's point within 1% of the
// centre's distance from its tangent plane; and as above, the same material, roughness or
// neither (same_as). No pass crosses the box's edges or the silhouettes; (e)'s passes do not
// cross an edge between tiles of different materials (tiles of one material meet at corners
// only). Measured on the default run, (d) with material-only taps as (e) instead: mean error
// 8.0 / 5.1 / 4.2% at K = 1 / 4 / 16 (README, shadows section). Cost per shaded pixel: two
// filters of 2 (2R + 1) taps of 2 values each for (d), one of 2 (2R + 1) taps of 3 values for
// (e); timed with the shading (measure.hpp).
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

/// What a tap must share with the centre pixel besides its surface (kind, normal, plane): its
/// material (any value), its roughness (the specular sums: f is GGX without Fresnel, so tiles of
/// one roughness have the same f), or nothing (the diffuse sums: f = cos / pi for every material).
enum class same_as { material, roughness, geometry };

/// What the filter compares of two pixels: the hit, its material's roughness, whether its material
/// has a diffuse term, and the distance from the centre's tangent plane that a tap may have (1% of
/// the centre's distance from the eye).
struct filter_pixel {
    const pixel_hit* hit;
    float roughness;
    bool diffuse;
    float plane_tolerance;
};

inline std::vector<filter_pixel> filter_pixels(const std::vector<pixel_hit>& hits, const scene& s) {
    std::vector<filter_pixel> f(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i) {
        const material* m = hits[i].shaded() ? &s.materials[static_cast<std::size_t>(hits[i].material)] : nullptr;
        f[i] = {&hits[i], m ? m->roughness : -1.0f, m && m->albedo != vec3(0.0f), 0.01f * glm::length(hits[i].p - s.eye)};
    }
    return f;
}

/// Whether the tap b lies on the surface of the centre pixel a and shares what `match` asks. Sums
/// are shared only between pixels whose materials both have a diffuse term or both have none: the
/// sample plan differs between them (without a diffuse term no sample is drawn from the light's
/// area, and the sums are unbiased only within the LTC's support: ltc::ratio_estimates).
inline bool same_surface(const filter_pixel& a, const filter_pixel& b, same_as match) {
    const pixel_hit &h = *a.hit, &t = *b.hit;
    if (h.kind != t.kind || !h.shaded() || a.diffuse != b.diffuse) return false;
    if (match == same_as::material && h.material != t.material) return false;
    if (match == same_as::roughness && a.roughness != b.roughness) return false;
    if (glm::dot(h.n, t.n) < 0.95f) return false;
    return std::abs(glm::dot(h.n, t.p - h.p)) <= a.plane_tolerance;
}

/// One pass of the separable filter along x (dx = 1) or y: out[i] = sum_j w_ij in[j] / sum_j w_ij
/// over the taps j on i's surface (the centre always is).
template <std::size_t N>
void filter_pass(const std::vector<filter_pixel>& pixels, same_as match, int W, int H, int radius, bool along_x,
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
                if (j != i && !same_surface(pixels[i], pixels[j], match)) continue;
                const double w = g[static_cast<std::size_t>(std::abs(k))];
                weight += w;
                for (std::size_t c = 0; c < N; ++c) sum[c] += w * in[j][c];
            }
            for (std::size_t c = 0; c < N; ++c) out[i][c] = sum[c] / weight;
        }
    });
}

/// The filter (rows, then columns) of N values per pixel, its taps on the centre's surface and
/// sharing what `match` asks.
template <std::size_t N>
std::vector<std::array<double, N>> cross_bilateral(const std::vector<filter_pixel>& pixels, same_as match, int W, int H,
                                                   int radius, unsigned threads, std::vector<std::array<double, N>> v) {
    if (radius <= 0) return v;
    std::vector<std::array<double, N>> rows(v.size());
    filter_pass(pixels, match, W, H, radius, true, threads, v, rows);
    filter_pass(pixels, match, W, H, radius, false, threads, rows, v);
    return v;
}

/// (d): each pixel's radiance from its analytic terms and the filtered estimates (file comment).
inline void denoise_ratio(const std::vector<pixel_hit>& hits, const scene& s, int W, int H, int radius,
                          unsigned threads, std::vector<shaded_pixel>& px) {
    const std::vector<filter_pixel> pixels = filter_pixels(hits, s);
    std::vector<std::array<double, 2>> spec(px.size()), diff(px.size());
    for (std::size_t i = 0; i < px.size(); ++i) {
        spec[i] = {px[i].specular_estimates.visible, px[i].specular_estimates.total};
        diff[i] = {px[i].diffuse_estimates.visible, px[i].diffuse_estimates.total};
    }
    spec = cross_bilateral(pixels, same_as::roughness, W, H, radius, threads, std::move(spec));
    diff = cross_bilateral(pixels, same_as::geometry, W, H, radius, threads, std::move(diff));
    for (std::size_t i = 0; i < px.size(); ++i) {
        if (!hits[i].shaded()) continue;
        const ltc::polygon_light_result<double> r = ltc::ratio_shading(
            px[i].analytic, ltc::ratio_estimates<double>{spec[i][0], spec[i][1]}, {diff[i][0], diff[i][1]});
        px[i].radiance = r.specular + r.diffuse;
    }
}

/// (e): each pixel's radiance filtered (its taps of the centre's material).
inline void denoise_radiance(const std::vector<pixel_hit>& hits, const scene& s, int W, int H, int radius,
                             unsigned threads, std::vector<shaded_pixel>& px) {
    std::vector<std::array<double, 3>> v(px.size());
    for (std::size_t i = 0; i < px.size(); ++i) v[i] = {px[i].radiance.r, px[i].radiance.g, px[i].radiance.b};
    v = cross_bilateral(filter_pixels(hits, s), same_as::material, W, H, radius, threads, std::move(v));
    for (std::size_t i = 0; i < px.size(); ++i)
        if (hits[i].shaded()) px[i].radiance = dvec3(v[i][0], v[i][1], v[i][2]);
}

}  // namespace shadows
