// shadows/denoise.hpp -- methods (d) and (e): a cross-bilateral filter over the image, applied
//   (d)  to (a)'s two Monte Carlo estimates per term (ltc::ratio_estimates: the sums of f V / p
//        and f / p over the same samples), each filtered on its own, the pixel's analytic terms
//        times the ratio of the filtered sums (ltc::ratio_shading). This is how Heitz, Hill and
//        McGuire (I3D 2018) denoise: the filter blurs the visibility only; the analytic shading,
//        its highlights and its tile edges stay sharp, and where no neighbour is shadowed the
//        sums are the same and the ratio is exactly 1 (with --ltc-correction off; by default,
//        below, the specular term keeps the filtered GGX / LTC mismatch there). The sums' f carries no albedo and no
//        Fresnel term, so they are shared across materials: the diffuse sums (f = cos / pi) over
//        the whole surface, the specular ones (GGX) between tiles of the same roughness; but not
//        between materials with and without a diffuse term (same_surface: their sample plans
//        differ); by default (--ltc-correction on) the specular term instead from the filtered
//        estimates of f V and their analytic values, per part of Hill's Fresnel split (f and
//        f (1 - V.H)^5: ltc::corrected_specular), which corrects the LTC's fitting error as well
//        as the shadows (the pixel's own analytic values times the filtered Monte Carlo estimate
//        relative to the filtered analytic one);
//   (e)  to (c)'s radiance, its taps of the centre's material only (the radiance carries the
//        albedo and the Fresnel term): the same filter on plain Monte Carlo, for a fair
//        comparison; it blurs the shading too. (c) records no blockers: (e) keeps the radius R
//        everywhere, where (d) by default takes a radius per pixel (below).
// The filter: separable (rows, then columns: (2r + 1) taps each instead of (2r + 1)^2), Gaussian in
// pixels (sigma = r / 2, r the pixel's radius: R, or (d)'s own), each tap kept only on the same
// surface as the centre pixel: the same kind (floor or occluder), normals within 18 degrees, and
// the tap's point within 1% of the centre's distance from its tangent plane; and as above, the same
// material, roughness or neither (same_as). No pass crosses the box's edges or the silhouettes;
// (e)'s passes do not cross an edge between tiles of different materials (tiles of one material
// meet at corners only). Measured on the default run of an earlier commit (R = 4, no LTC
// correction), (d) with material-only taps as (e) instead: mean error 8.0 / 5.1 / 4.2% at
// K = 1 / 4 / 16 against 7.6 / 4.9 / 3.9%. R: --denoise-radius, or auto_radius(K); (d)'s radius by
// default per pixel, in [1, R], from the penumbra's width there (penumbra_radii; --filter-radius
// fixed: R everywhere, the earlier images byte for byte). Cost per shaded pixel: one filter of
// 2 (2R + 1) taps for (d), each tap's surface tested once for its 4 specular values (2 with
// --ltc-correction off; taps of the centre's roughness) and its 2 diffuse ones (any material), and
// one of 2 (2R + 1) taps of 3 values for (e); with the penumbra's radii, a filter of 2 values more
// (the blocker distances), and (d)'s shadow rays are closest-hit queries instead of any-hit ones;
// timed with the shading (measure.hpp).
#pragma once

#include "camera.hpp"
#include "common/pinhole.hpp"
#include "common/threads.hpp"
#include "filter_settings.hpp"
#include "scene.hpp"
#include "shade_mis.hpp"  // shaded_pixel

#include <ltc/shading/shade_shadowed.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadows {

/// The filter's radius for K samples per pixel ((d)) or iterations ((e)) where --denoise-radius
/// gives none: R = 4 (K / 4)^(-1/6), rounded; a heuristic. A kernel smoother over a 2-D image
/// balances its squared bias (~ R^4 where the signal is smooth) against its variance
/// (~ 1 / (K R^2)) at R ~ K^(-1/6) (the optimal bandwidth n^(-1/(d + 4)) of Wand and Jones,
/// "Kernel Smoothing", 1995, ch. 4, d = 2); at edges (the penumbrae) the squared bias grows as R
/// and the rate is K^(-1/3): the slower rate is taken, anchored at R = 4 for K = 4, the radius
/// chosen before measuring. K = 1 gives 5, K = 2 to 8 give 4, K = 16 to 64 give 3, K = 128 and
/// 256 give 2. Measured against fixed radii: README, shadows section.
inline int auto_radius(int K) {
    return std::max(1, static_cast<int>(std::lround(4.0 * std::pow(std::max(K, 1) / 4.0, -1.0 / 6.0))));
}

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

/// Whether the tap b lies on the surface of the centre pixel a (kind, normal, plane). Sums are
/// shared only between pixels whose materials both have a diffuse term or both have none: the
/// sample plan differs between them (without a diffuse term no sample is drawn from the light's
/// area, and the sums are unbiased only within the LTC's support: ltc::ratio_estimates).
inline bool same_surface(const filter_pixel& a, const filter_pixel& b) {
    const pixel_hit &h = *a.hit, &t = *b.hit;
    if (h.kind != t.kind || !h.shaded() || a.diffuse != b.diffuse) return false;
    if (glm::dot(h.n, t.n) < 0.95f) return false;
    return std::abs(glm::dot(h.n, t.p - h.p)) <= a.plane_tolerance;
}

/// Whether the tap b, on a's surface, shares what `match` asks.
inline bool shares(const filter_pixel& a, const filter_pixel& b, same_as match) {
    if (match == same_as::material) return a.hit->material == b.hit->material;
    return match != same_as::roughness || a.roughness == b.roughness;
}

/// One pass of the separable filter along x (along_x) or y: out[i] = sum_j w_ij in[j] / sum_j w_ij
/// over the taps j on i's surface (the centre always is) that share what match_a asks for the
/// first NA values, what match_b asks for the others: two filters in one pass over the taps
/// (each value's sum and weights are those of a pass of its own, bit for bit).
/// With `radii`, pixel i's own radius along this pass, radii[i] (at most `radius`), instead of
/// `radius`: sigma = radii[i] / 2, and radius 0 keeps the pixel's values.
template <std::size_t N, std::size_t NA>
void filter_pass(const std::vector<filter_pixel>& pixels, same_as match_a, same_as match_b, int W, int H, int radius,
                 bool along_x, unsigned threads, const std::vector<std::array<double, N>>& in,
                 std::vector<std::array<double, N>>& out, const std::vector<std::uint8_t>* radii = nullptr) {
    static_assert(NA <= N, "the first NA of N values");
    // gauss[r][k]: the weight of tap k at radius r (sigma = r / 2).
    std::vector<std::vector<double>> gauss(static_cast<std::size_t>(radius) + 1);
    for (int r = 1; r <= radius; ++r) {
        std::vector<double>& g = gauss[static_cast<std::size_t>(r)];
        g.resize(static_cast<std::size_t>(r) + 1);
        const double sigma = 0.5 * r;
        for (int k = 0; k <= r; ++k) g[static_cast<std::size_t>(k)] = std::exp(-0.5 * k * k / (sigma * sigma));
    }
    ltc_examples::for_each_row(H, threads, [&](int y) {
        for (int x = 0; x < W; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * W + x;
            out[i] = in[i];
            if (!pixels[i].hit->shaded()) continue;
            const int r_i = radii != nullptr ? std::min(static_cast<int>((*radii)[i]), radius) : radius;
            if (r_i <= 0) continue;
            const std::vector<double>& g = gauss[static_cast<std::size_t>(r_i)];
            std::array<double, N> sum{};
            double weight_a = 0, weight_b = 0;
            for (int k = -r_i; k <= r_i; ++k) {
                const int xx = along_x ? x + k : x, yy = along_x ? y : y + k;
                if (xx < 0 || xx >= W || yy < 0 || yy >= H) continue;
                const std::size_t j = static_cast<std::size_t>(yy) * W + xx;
                if (j != i && !same_surface(pixels[i], pixels[j])) continue;
                const double w = g[static_cast<std::size_t>(std::abs(k))];
                if (j == i || shares(pixels[i], pixels[j], match_a)) {
                    weight_a += w;
                    for (std::size_t c = 0; c < NA; ++c) sum[c] += w * in[j][c];
                }
                if (NA < N && (j == i || shares(pixels[i], pixels[j], match_b))) {
                    weight_b += w;
                    for (std::size_t c = NA; c < N; ++c) sum[c] += w * in[j][c];
                }
            }
            for (std::size_t c = 0; c < N; ++c) out[i][c] = sum[c] / (c < NA ? weight_a : weight_b);
        }
    });
}

/// Each pixel's filter radius along x and along y (filter_pass's radii).
struct pixel_radii {
    std::vector<std::uint8_t> x, y;
};

/// The filter (rows, then columns) of N values per pixel, its taps on the centre's surface and
/// sharing what match_a asks for the first NA values, what match_b asks for the others; with
/// `radii`, each pixel's own radius per pass (penumbra_radii), at most `radius`.
template <std::size_t N, std::size_t NA>
std::vector<std::array<double, N>> cross_bilateral(const std::vector<filter_pixel>& pixels, same_as match_a,
                                                   same_as match_b, int W, int H, int radius, unsigned threads,
                                                   std::vector<std::array<double, N>> v,
                                                   const pixel_radii* radii = nullptr) {
    if (radius <= 0) return v;
    std::vector<std::array<double, N>> rows(v.size());
    filter_pass<N, NA>(pixels, match_a, match_b, W, H, radius, true, threads, v, rows, radii ? &radii->x : nullptr);
    filter_pass<N, NA>(pixels, match_a, match_b, W, H, radius, false, threads, rows, v, radii ? &radii->y : nullptr);
    return v;
}

/// The length on the surface (point p, unit normal n, seen along the unit ray direction d) that
/// one pixel's step along the image axis `axis` covers: the step depth * pixel_size * axis on the
/// plane at p's depth, carried along d onto the surface's tangent plane (first order; |n.d|
/// floored at 1e-3 at silhouettes).
inline double pixel_footprint(const ltc_examples::pinhole& camera, const vec3& eye, const vec3& p, const vec3& n,
                              const vec3& d, const vec3& axis) {
    const double depth = static_cast<double>(glm::dot(p - eye, camera.forward()));
    const double nd = static_cast<double>(glm::dot(n, d));
    const double nd_floored = std::copysign(std::max(std::abs(nd), 1e-3), nd);
    const glm::dvec3 step = glm::dvec3(axis) - glm::dvec3(d) * (static_cast<double>(glm::dot(n, axis)) / nd_floored);
    return depth * static_cast<double>(camera.pixel_size()) * glm::length(step);
}

/// (d) with --filter-radius penumbra: each pixel's radius from the width of the penumbra there,
/// as percentage-closer soft shadows estimate it (Fernando, "Percentage-Closer Soft Shadows",
/// SIGGRAPH 2005 sketch): a blocker at t_b from the point, towards a light of extent w_l at t_l,
/// casts a penumbra about w_l t_b / (t_l - t_b) wide (ltc::penumbra_width). t_b / (t_l - t_b),
/// which the library sums per pixel (the result's `blockers`), is averaged over the
/// occluded samples of the pixel and of its neighbours on its surface (the filter of radius R,
/// weighted by their counts: a lit pixel next to a penumbra takes its neighbours'). w_l is an
/// isotropic proxy, sqrt(area), for a light whose extent depends on the direction across the
/// edge (2.6 x 1 here; the receiver's tilt towards the light is left out too: per-axis projected
/// extents measured no better). In pixels: the width over the pixel's footprint along the
/// image's rows and along its columns (pixel_footprint: the surface seen obliquely is
/// foreshortened). The radius is half of it (sigma = r / 2, a quarter of the width, over which a
/// Gaussian blurs a ramp little: a factor chosen before measuring, for the proxy above), rounded,
/// in [1, R]. No occluded sample nearby: R (every ratio is 1 there). R >= 1.
inline pixel_radii penumbra_radii(const std::vector<filter_pixel>& pixels, const std::vector<shaded_pixel>& px,
                                  const scene& s, int W, int H, int radius, unsigned threads) {
    std::vector<std::array<double, 2>> v(px.size());
    for (std::size_t i = 0; i < px.size(); ++i)
        v[i] = {px[i].blockers.ratio_sum, px[i].blockers.occluded};
    v = cross_bilateral<2, 2>(pixels, same_as::geometry, same_as::geometry, W, H, radius, threads, std::move(v));
    const double light_extent = std::sqrt(static_cast<double>(s.light_area()));
    const ltc_examples::pinhole camera(s.eye, s.target, s.vfov_deg, W, H);
    pixel_radii r{std::vector<std::uint8_t>(px.size(), 0), std::vector<std::uint8_t>(px.size(), 0)};
    const auto clamped = [radius](double w) {  // half the width, in [1, radius]
        return static_cast<std::uint8_t>(std::clamp(static_cast<int>(std::lround(std::min(0.5 * w, 255.0))), 1, radius));
    };
    for (std::size_t i = 0; i < px.size(); ++i) {
        const pixel_hit& h = *pixels[i].hit;
        if (!h.shaded()) continue;
        if (!(v[i][1] > 0)) {
            r.x[i] = r.y[i] = static_cast<std::uint8_t>(radius);
            continue;
        }
        const double penumbra = ltc::penumbra_width(light_extent, ltc::blocker_estimates<double>{v[i][0], v[i][1]});
        r.x[i] = clamped(penumbra / pixel_footprint(camera, s.eye, h.p, h.n, -h.v, camera.right()));
        r.y[i] = clamped(penumbra / pixel_footprint(camera, s.eye, h.p, h.n, -h.v, camera.up()));
    }
    return r;
}

/// (d)'s values filtered in one pass over the taps: NS specular values per pixel (taps of the
/// centre's roughness), then the diffuse sums {visible, total} (taps anywhere on its surface).
template <std::size_t NS, typename SpecularValues>
std::vector<std::array<double, NS + 2>> filter_estimates(const std::vector<filter_pixel>& pixels,
                                                         const std::vector<shaded_pixel>& px,
                                                         SpecularValues&& specular_values, int W, int H, int radius,
                                                         unsigned threads, const pixel_radii* radii) {
    std::vector<std::array<double, NS + 2>> v(px.size());
    for (std::size_t i = 0; i < px.size(); ++i) {
        const std::array<double, NS> a = specular_values(px[i]);
        for (std::size_t c = 0; c < NS; ++c) v[i][c] = a[c];
        v[i][NS] = px[i].diffuse_estimates.visible;
        v[i][NS + 1] = px[i].diffuse_estimates.total;
    }
    return cross_bilateral<NS + 2, NS>(pixels, same_as::roughness, same_as::geometry, W, H, radius, threads,
                                       std::move(v), radii);
}

/// (d): each pixel's radiance from its analytic terms and the filtered estimates (file comment).
/// radius: R (resolved: not -1); filter.penumbra only with R >= 1 (render_method).
inline void denoise_ratio(const std::vector<pixel_hit>& hits, const scene& s, int W, int H, int radius,
                          const filter_settings& filter, unsigned threads, std::vector<shaded_pixel>& px) {
    const std::vector<filter_pixel> pixels = filter_pixels(hits, s);
    const bool correct = filter.ltc_correction, penumbra = filter.penumbra_at(radius);
    pixel_radii radii;
    if (penumbra) radii = penumbra_radii(pixels, px, s, W, H, radius, threads);
    const pixel_radii* own = penumbra ? &radii : nullptr;
    const auto diffuse = [&](std::size_t i, double visible, double total) {
        return ltc::ratio_shading(px[i].analytic.diffuse, ltc::ratio_estimates<double>{visible, total});
    };
    if (correct) {
        // {visible, analytic} of both parts of the specular term: f and f (1 - V.H)^5.
        const auto v = filter_estimates<4>(
            pixels, px,
            [](const shaded_pixel& p) {
                const auto &e = p.specular_estimates, &ef = p.specular_fresnel_estimates;
                return std::array<double, 4>{e.visible, e.analytic, ef.visible, ef.analytic};
            },
            W, H, radius, threads, own);
        for (std::size_t i = 0; i < px.size(); ++i) {
            if (!hits[i].shaded()) continue;
            const material& m = s.materials[static_cast<std::size_t>(hits[i].material)];
            px[i].radiance = ltc::corrected_specular(dvec3(m.f0), dvec3(s.light_radiance),
                                                     px[i].specular_estimates.analytic,
                                                     px[i].specular_fresnel_estimates.analytic,
                                                     {v[i][0], 0.0, v[i][1]}, {v[i][2], 0.0, v[i][3]}) +
                             diffuse(i, v[i][4], v[i][5]);
        }
        return;
    }
    const auto v = filter_estimates<2>(
        pixels, px,
        [](const shaded_pixel& p) {
            return std::array<double, 2>{p.specular_estimates.visible, p.specular_estimates.total};
        },
        W, H, radius, threads, own);
    for (std::size_t i = 0; i < px.size(); ++i)
        if (hits[i].shaded())
            px[i].radiance = ltc::ratio_shading(px[i].analytic.specular, ltc::ratio_estimates<double>{v[i][0], v[i][1]}) +
                             diffuse(i, v[i][2], v[i][3]);
}

/// (e): each pixel's radiance filtered (its taps of the centre's material).
inline void denoise_radiance(const std::vector<pixel_hit>& hits, const scene& s, int W, int H, int radius,
                             unsigned threads, std::vector<shaded_pixel>& px) {
    std::vector<std::array<double, 3>> v(px.size());
    for (std::size_t i = 0; i < px.size(); ++i) v[i] = {px[i].radiance.r, px[i].radiance.g, px[i].radiance.b};
    v = cross_bilateral<3, 3>(filter_pixels(hits, s), same_as::material, same_as::material, W, H, radius, threads,
                              std::move(v));
    for (std::size_t i = 0; i < px.size(); ++i)
        if (hits[i].shaded()) px[i].radiance = dvec3(v[i][0], v[i][1], v[i][2]);
}

}  // namespace shadows
