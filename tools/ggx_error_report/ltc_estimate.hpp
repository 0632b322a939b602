// ggx_error_report/ltc_estimate.hpp -- the LTC estimate (F0 magnitude + (1 - F0) fresnel) I_ltc
// of a configuration (F0 = 1 by default: magnitude * I_ltc) with each horizon-clipping method
// (exact, clip-first, clip-once, sphere, sphere-tab: main.cpp's file comment), from any table (a
// fetch function), for the whole grid.
#pragma once

#include "grid.hpp"

#include <ltc/shading/clipless.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace ggx_error_report {

enum method_id { exact, clip_first, clip_once, sphere, sphere_tab, method_count };
const char* const method_names[method_count] = {"exact", "clip-first", "clip-once", "sphere", "sphere-tab"};

using fetch_fn = std::function<ltc::ltc_coefficients<double>(double, double)>;

/// --f0 F0: the specular colour of every estimate and its ground truth, Schlick's factor
/// F = F0 + (1 - F0) (1 - V.H)^5 in the integrand rho cos F, and the tables' F0 magnitude +
/// (1 - F0) fresnel (Hill 2016); 0.04 is a dielectric's, whose specular term at grazing views is
/// largely the Fresnel part. The default, 1, is rho cos and the magnitude channel alone (no Fresnel).
inline double report_f0 = 1.0;

/// The factor of `lobe` that scales its LTC integral at F0 = report_f0.
inline double part_scale(const ltc::ltc_coefficients<double>& lobe) {
    return report_f0 * lobe.magnitude + (1.0 - report_f0) * lobe.fresnel;
}

/// part_scale(lobe) * I_ltc for the configuration, with the given method.
inline double ltc_estimate(const config& c, const fetch_fn& fetch, int m) {
    const double theta = thetas[c.theta] * deg;
    const dvec3 N(0, 0, 1), V(std::sin(theta), 0, std::cos(theta)), P(0);
    const auto frame = ltc::make_shading_frame(N, V);
    const auto lobe = fetch(frame.cos_theta_v, roughnesses[c.rough]);
    const std::size_t n = c.vertices.size();
    double I = 0;
    switch (m) {
        case exact: I = ltc::integrate_polygon_light(frame, lobe.m_inv, P, c.vertices.data(), n, ltc::horizon_clipping::ltc_space).ltc; break;
        case clip_first: I = ltc::integrate_polygon_light(frame, lobe.m_inv, P, c.vertices.data(), n, ltc::horizon_clipping::shading_first).ltc; break;
        case clip_once: {
            const auto at = [&](std::size_t i) { return frame.to_local(c.vertices[i] - P); };
            I = ltc::detail::integrals_shading_first<double>(lobe.m_inv, at, n, false).ltc;
            break;
        }
        case sphere: I = ltc::integrate_polygon_light(frame, lobe.m_inv, P, c.vertices.data(), n, ltc::horizon_clipping::sphere_analytic).ltc; break;
        default: I = ltc::integrate_polygon_light(frame, lobe.m_inv, P, c.vertices.data(), n, ltc::horizon_clipping::sphere_table).ltc; break;
    }
    return part_scale(lobe) * std::max(0.0, I);  // the lights are front-facing: one-sided
}

/// part_scale of the table at the configuration's view angle and roughness: the albedo that the
/// significance threshold and the "/alb" columns divide by.
inline double albedo_at(const config& c, const fetch_fn& fetch) {
    return part_scale(fetch(std::cos(thetas[c.theta] * deg), roughnesses[c.rough]));
}

struct evaluation {
    std::vector<double> value[method_count];  // LTC estimates per configuration
    std::vector<double> albedo;               // part_scale of the table at the configuration
};

inline evaluation evaluate(const std::vector<config>& grid, const fetch_fn& fetch, bool all_methods) {
    evaluation ev;
    for (int m = 0; m < method_count; ++m) ev.value[m].resize(grid.size());
    ev.albedo.resize(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const auto& c = grid[i];
        ev.albedo[i] = albedo_at(c, fetch);
        for (int m = 0; m < method_count; ++m)
            if (all_methods || m == exact) ev.value[m][i] = ltc_estimate(c, fetch, m);
    }
    return ev;
}


}  // namespace ggx_error_report
