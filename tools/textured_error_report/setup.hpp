// textured_error_report/setup.hpp -- the report's inputs: the four 64 x 64 textures, their
// Monte Carlo area densities, and the grid of lights and lobes (main.cpp's file comment).
#pragma once

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/reference/textured_ground_truth.hpp>
#include <ltc/shading/ggx_fetch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace textured_error_report {

using dvec3 = glm::dvec3;
constexpr double pi = 3.141592653589793;

inline double sum(const dvec3& c) { return c.x + c.y + c.z; }

// ---- Textures ------------------------------------------------------------------------------

enum texture_id { gradient, blobs, checker, bright_detail, texture_count };

struct image {
    std::string name;
    int w = 64, h = 64;
    std::vector<dvec3> px;  ///< row-major, v = 0 on the first row
    dvec3 at(int x, int y) const { return px[std::size_t(y) * w + x]; }
};

inline image make_texture(int which) {
    static const char* names[texture_count] = {"gradient", "blobs", "checker", "bright detail"};
    image im;
    im.name = names[which];
    im.px.resize(std::size_t(im.w) * im.h);
    struct blob {
        dvec3 colour;
        double u, v, sigma;
    };
    const blob bs[3] = {{dvec3(1.0, 0.3, 0.1), 0.3, 0.3, 0.12},
                        {dvec3(0.1, 0.8, 0.3), 0.7, 0.6, 0.15},
                        {dvec3(0.2, 0.3, 1.2), 0.45, 0.85, 0.08}};
    for (int y = 0; y < im.h; ++y)
        for (int x = 0; x < im.w; ++x) {
            const double u = (x + 0.5) / im.w, v = (y + 0.5) / im.h;
            dvec3 c;
            switch (which) {
                case gradient: c = dvec3(u, v, 1 - u * v); break;
                case blobs:
                    c = dvec3(0.05);
                    for (const blob& b : bs) {
                        const double r2 = (u - b.u) * (u - b.u) + (v - b.v) * (v - b.v);
                        c += b.colour * std::exp(-r2 / (2 * b.sigma * b.sigma));
                    }
                    break;
                // Shifted by 2 texels along u: every light and lobe here is symmetric under
                // u -> 1 - u, which would swap an unshifted checker's colours and make every
                // method that returns the texture's mean exact.
                case checker: c = dvec3((((x + 2) / 4 + y / 4) % 2) ? 1.0 : 0.05); break;
                default:
                    c = dvec3(0.02);
                    if (x >= 44 && x < 47 && y >= 21 && y < 24) c = dvec3(100.0, 80.0, 60.0);
            }
            im.px[std::size_t(y) * im.w + x] = c;
        }
    return im;
}

/// The area density of the Monte Carlo (half uniform, half proportional to these weights): the
/// RGB sum of each texel's 3 x 3 neighbourhood's brightest texel (dilated by one texel, so that
/// it also covers the bilinear texture, which spreads each texel over its neighbours).
inline ltc::textured_ground_truth::texel_distribution luminance_density(const image& im) {
    std::vector<double> wgt(im.px.size());
    for (int y = 0; y < im.h; ++y)
        for (int x = 0; x < im.w; ++x) {
            double m = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    m = std::max(m, sum(im.at(std::min(std::max(x + dx, 0), im.w - 1),
                                              std::min(std::max(y + dy, 0), im.h - 1))));
            wgt[std::size_t(y) * im.w + x] = m;
        }
    return ltc::textured_ground_truth::texel_distribution(im.w, im.h, wgt.data());
}

// ---- The grid of lights and lobes ----------------------------------------------------------

constexpr int lobe_count = 5, view_count = 4, dist_count = 3, orient_count = 3;
constexpr double roughnesses[lobe_count] = {-1, 0.1, 0.25, 0.5, 1.0};  // -1: diffuse (M = I)
constexpr double views[view_count] = {0, 30, 60, 80};                  // theta_v, degrees
constexpr double dists[dist_count] = {0.5, 1.5, 4};
inline const char* const lobe_names[lobe_count] = {"diffuse", "r 0.1", "r 0.25", "r 0.5", "r 1"};
inline const char* const orient_names[orient_count] = {"facing", "tilted 60", "vertical"};

struct config {
    int lobe = 0, view = 0, dist = 0, orient = 0;
    dvec3 V{0.0};
    dvec3 quad[4];                                  ///< uv (0,0), (1,0), (1,1), (0,1)
    ltc::ltc_coefficients<double> coeff;            ///< the GGX table's entry (unused for diffuse)
    ltc::transformed<ltc::clamped_cosine<double>> d{glm::dmat3(1.0)};
    double i_d = 0;                                 ///< exact, two-sided
    bool diffuse() const { return roughnesses[lobe] < 0; }
};

/// All 5 x 4 x 3 x 3 = 180 configurations, lobe-major.
inline std::vector<config> make_grid() {
    std::vector<config> grid;
    for (int ri = 0; ri < lobe_count; ++ri)
        for (int vi = 0; vi < view_count; ++vi)
            for (int di = 0; di < dist_count; ++di)
                for (int oi = 0; oi < orient_count; ++oi) {
                    config c;
                    c.lobe = ri, c.view = vi, c.dist = di, c.orient = oi;
                    const double th = views[vi] * pi / 180;
                    c.V = dvec3(std::sin(th), 0, std::cos(th));
                    const double el = 45 * pi / 180;
                    const dvec3 dir(-std::cos(el), 0, std::sin(el));  // mirror side, elevation 45 deg
                    const dvec3 centre = dists[di] * dir;
                    dvec3 n = -dir;  // facing the shading point
                    if (oi == 1) {   // rotated by 60 deg about the horizontal axis y
                        const double a = 60 * pi / 180;
                        n = dvec3(n.x * std::cos(a) + n.z * std::sin(a), 0, -n.x * std::sin(a) + n.z * std::cos(a));
                    } else if (oi == 2) {  // vertical, its normal towards the shading point's side
                        n = dvec3(1, 0, 0);
                    }
                    const dvec3 t(0, 1, 0);
                    const dvec3 b = glm::normalize(glm::cross(n, t));
                    c.quad[0] = centre - 0.5 * t - 0.5 * b;
                    c.quad[1] = centre + 0.5 * t - 0.5 * b;
                    c.quad[2] = centre + 0.5 * t + 0.5 * b;
                    c.quad[3] = centre - 0.5 * t + 0.5 * b;
                    c.coeff = ltc::ggx::fetch<double>(std::cos(th), c.diffuse() ? 0.5 : roughnesses[ri]);
                    c.d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(
                        c.diffuse() ? glm::dmat3(1.0) : c.coeff.m_inv);
                    c.i_d = c.d.integrate(c.quad, 4);
                    grid.push_back(c);
                }
    return grid;
}

/// The Monte Carlo seed of estimator `kind` for configuration `index` and texture `tex`
/// (tex = texture_count: the untextured one): fixed per configuration, so that the results do
/// not depend on the order or the thread that computes them.
inline std::uint64_t seed_of(std::size_t index, int tex, int kind) {
    return 1 + (std::uint64_t(index) * (texture_count + 1) + std::uint64_t(tex)) * 4 + std::uint64_t(kind);
}

}  // namespace textured_error_report
