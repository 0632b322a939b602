// textured_error_report/evaluate.hpp -- one configuration of the grid, every texture: the three
// methods of ltc/shading/textured_light.hpp, the full-refinement cells, and the Monte Carlo
// estimates (main.cpp's file comment says what each is).
#pragma once

#include "setup.hpp"

#include <ltc/brdf/ggx.hpp>
#include <ltc/reference/textured_ground_truth.hpp>
#include <ltc/shading/light_texture.hpp>
#include <ltc/shading/quick_cells.hpp>
#include <ltc/shading/textured_cells.hpp>
#include <ltc/shading/textured_light.hpp>

#include <cstddef>
#include <vector>

namespace textured_error_report {

// quick_means: quick_cells' leaves, every leaf its mean (integrate_quick_cells with use_fetch =
// false: what quick_cells does without the fetch in leaves wider than the lobe).
enum method_id { fetch, quick_means, quick_cells, exact_cells, method_count };
inline const char* const method_names[method_count] = {"fetch (paper)", "quick_cells, means", "quick_cells",
                                                       "exact_cells (64)"};

/// Everything measured for one configuration and one texture. Monte Carlo values are of the
/// RGB sum of the radiance (the errors sum RGB before the ratio).
struct texture_result {
    dvec3 approx[method_count];          ///< the methods' values (method_id)
    std::size_t integrals[method_count]; ///< polygon integrals per method (1 for the fetch)
    dvec3 full{0.0};                     ///< exact_cells with 64 x 64 cells: the texel-constant integral
    double truth = 0, truth_se = 0;      ///< MC of int L D, L texel-constant (nearest_image_lookup)
    double bilinear = 0;                 ///< MC of int L D, L bilinear: same seed and density
    double shading_truth = 0;            ///< MC of int L rho cos (GGX), L texel-constant; diffuse: = truth
    double sigma = 0;                    ///< the fetch's filter width (uv)
};

struct config_result {
    bool significant = false;  ///< I_D >= 1e-4 (the rest are skipped)
    double fit_truth = 0;      ///< MC of int rho cos (constant texture 1; GGX lobes only)
    texture_result tex[texture_count];
};

struct inputs {
    std::vector<image> textures;
    std::vector<ltc::light_texture<double>> prefiltered;
    std::vector<ltc::textured_ground_truth::texel_distribution> densities;
    std::size_t samples = std::size_t(1) << 15;
};

inline config_result evaluate(const config& c, std::size_t index, const inputs& in) {
    namespace gt = ltc::textured_ground_truth;
    config_result r;
    r.significant = c.i_d >= 1e-4;
    if (!r.significant) return r;
    const double alpha = roughnesses[c.lobe] * roughnesses[c.lobe];
    const gt::brdf_lobe<ltc::brdf::ggx<double>> brdf{c.V, alpha};
    const gt::ltc_lobe lobe{c.d};
    gt::options opt;
    opt.samples = in.samples;
    if (!c.diffuse()) {
        opt.seed = seed_of(index, texture_count, 0);
        r.fit_truth = gt::integrate(brdf, c.quad, [](double, double) { return dvec3(1.0); }, opt).mean.x;
    }
    for (int ti = 0; ti < texture_count; ++ti) {
        const image& im = in.textures[std::size_t(ti)];
        const auto& tex = in.prefiltered[std::size_t(ti)];
        const auto& density = in.densities[std::size_t(ti)];
        texture_result& t = r.tex[ti];
        const auto side = ltc::sidedness::two_sided;
        t.approx[fetch] = ltc::integrate_textured_quad(c.d, c.quad, tex, side);
        t.integrals[fetch] = 1;
        const auto means = ltc::integrate_quick_cells(c.d, c.quad, tex, side, false);
        t.approx[quick_means] = means.value;
        t.integrals[quick_means] = t.integrals[quick_cells] = means.integrals;  // the same leaves
        ltc::textured_policy p;
        p.method = ltc::textured_method::quick_cells;
        t.approx[quick_cells] = ltc::integrate_textured_quad(c.d, c.quad, tex, side, p);
        ltc::cell_budget exact;
        exact.max_cells = 64;
        const auto cells = ltc::integrate_textured_cells(c.d, c.quad, tex.cells(), side, exact);
        t.approx[exact_cells] = cells.value;
        t.integrals[exact_cells] = cells.integrals;
        ltc::cell_budget all;
        all.max_cells = std::size_t(im.w) * std::size_t(im.h);
        t.full = ltc::integrate_textured_cells(c.d, c.quad, tex.cells(), ltc::sidedness::two_sided, all).value;
        t.sigma = double(ltc::fetch_parameters(c.d.inverse_matrix(), c.quad).sigma);
        // The radiance as its RGB sum in all three channels: the estimate's .x is then the MC of
        // the RGB sum, with its own standard error.
        const auto nearest = [&](double u, double v) {
            return dvec3(sum(ltc::nearest_image_lookup(im.w, im.h, im.px.data(), u, v)));
        };
        const auto bilinear = [&](double u, double v) {
            return dvec3(sum(ltc::bilinear_image_lookup(im.w, im.h, im.px.data(), u, v)));
        };
        opt.seed = seed_of(index, ti, 0);
        const gt::estimate e = gt::integrate(lobe, c.quad, nearest, opt, &density);
        t.truth = e.mean.x;
        t.truth_se = e.standard_error.x;
        // Common random numbers: the same seed and density, so that the difference from the
        // truth is the reconstruction's, hardly the noise's.
        t.bilinear = gt::integrate(lobe, c.quad, bilinear, opt, &density).mean.x;
        if (c.diffuse()) {
            t.shading_truth = t.truth;
        } else {
            opt.seed = seed_of(index, ti, 1);
            t.shading_truth = gt::integrate(brdf, c.quad, nearest, opt, &density).mean.x;
        }
    }
    return r;
}

}  // namespace textured_error_report
