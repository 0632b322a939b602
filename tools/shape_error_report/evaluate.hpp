// shape_error_report/evaluate.hpp -- per configuration: the Monte Carlo truth of the real GGX
// (ltc/reference/shape_ground_truth.hpp), the LTC shading through shade_sphere_light /
// shade_disk_light / shade_line_light / shade_tube_light (double, F0 = 1, albedo = radiance = 1: specular =
// magnitude * I_ltc, diffuse = E), the disks' 2017 approximation and equal-area polygons, and the
// exact diffuse form factors, each computed without the code under test (main.cpp's comment).
#pragma once

#include "grid.hpp"

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/ellipse_integral.hpp>
#include <ltc/core/form_factor.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/brdf/ggx.hpp>
#include <ltc/reference/shape_ground_truth.hpp>
#include <ltc/shading/disk_light.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/line_light.hpp>
#include <ltc/core/sphere_form_factor.hpp>
#include <ltc/shading/sphere_light.hpp>
#include <ltc/shading/tube_light.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace shape_error_report {

namespace gt = ltc::ground_truth;

/// The clamped cosine as a "BRDF" (eval = max(0, L.z) / pi), cosine-sampled: the tube's form factor.
struct lambert {
    double eval(const dvec3&, const dvec3& L, double) const { return L.z > 0 ? L.z / pi : 0.0; }
    double pdf(const dvec3& V, const dvec3& L, double a) const { return eval(V, L, a); }
    dvec3 sample(const dvec3&, const glm::dvec2& u, double) const {
        const double r = std::sqrt(u.x), phi = 2 * pi * u.y;
        return {r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - u.x)};
    }
};

inline dvec3 view_of(const config& c) {
    const double t = thetas[c.theta] * deg;
    return {std::sin(t), 0, std::cos(t)};
}

/// Exact form factor of the one-sided disk: the equal-area regular 4096-gon through the polygon
/// form factor (eq. 11; no ellipse code). Its error falls as n^-4 unclipped, n^-2.7 clipped
/// (ellipse_integral.hpp): below 1e-9 here.
inline double disk_form_factor(const config& c) {
    constexpr int n = 4096;
    const dvec3 nrm = glm::normalize(c.normal), t1 = ltc::orthonormal_tangent(nrm), t2 = glm::cross(t1, nrm);
    const double step = 2 * pi / n, rho = c.radius * std::sqrt(step / std::sin(step));
    std::vector<dvec3> v(n);
    for (int i = 0; i < n; ++i)  // t1 x t2 = -normal: clockwise seen from the lit side
        v[std::size_t(i)] = c.centre + rho * (std::cos(step * i) * t1 + std::sin(step * i) * t2);
    return ltc::form_factor(v.data(), v.size(), ltc::sidedness::one_sided);
}

/// The thin line's closed form (L2 of ltc/core/line_integral.hpp, in its atan2 form), clipped to
/// z >= 0, times the tube's diameter.
inline double line_form_factor(const config& c) {
    dvec3 a = c.p0, b = c.p1;
    if (a.z <= 0 && b.z <= 0) return 0;
    const dvec3 span = b - a, t = glm::normalize(span), foot = a - glm::dot(a, t) * t;
    const double d = glm::length(foot);
    const dvec3 n = foot / d;
    if (a.z < 0) a += a.z / (a.z - b.z) * span;
    if (b.z < 0) b -= b.z / (b.z - a.z) * span;
    const auto F = [&](const dvec3& x) {
        const double th = std::atan2(glm::dot(x, t), d);
        return n.z * (th + std::sin(th) * std::cos(th)) + t.z * std::sin(th) * std::sin(th);
    };
    return 2 * c.radius * (F(b) - F(a)) / (2 * pi * d);
}

/// The LTC side: shading, the 2017 disk, polygons, and the exact diffuse form factor.
inline void evaluate_ltc(config& c) {
    const dvec3 P(0), N(0, 0, 1), V = view_of(c), one(1);
    const double roughness = roughnesses[c.rough];
    const ltc::ltc_coefficients<double> lobe = ltc::ggx::fetch<double>(V.z, roughness);
    const auto spec = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(lobe.m_inv);
    constexpr auto one_sided = ltc::sidedness::one_sided;
    c.albedo = lobe.magnitude;
    ltc::polygon_light_result<double> r;
    if (c.shape == sphere) {
        r = ltc::shade_sphere_light(P, N, V, roughness, one, one, one, c.centre, c.radius);
        const ltc::sphere_view<double> s = ltc::view_sphere(P, c.centre, c.radius);
        c.ltc_2017 = s.kind == ltc::sphere_view<double>::disk
                         ? lobe.magnitude * ltc::integrate_disk_2017(spec, s.centre, s.normal, s.radius, one_sided)
                         : r.specular.x;
        const double d = glm::length(c.centre), f = (c.radius / d) * (c.radius / d);
        c.diffuse_exact = c.inside ? 1.0 : ltc::clipless::sphere_form_factor(f, c.centre.z / d);  // Snyder 1996
    } else if (c.shape == disk) {
        r = ltc::shade_disk_light(P, N, V, roughness, one, one, one, c.centre, c.normal, c.radius, one_sided);
        c.ltc_2017 = lobe.magnitude * ltc::integrate_disk_2017(spec, c.centre, c.normal, c.radius, one_sided);
        for (int k = 0; k < 4; ++k)
            c.polygon[k] = lobe.magnitude * ltc::integrate_disk_polygon(spec, c.centre, c.normal, c.radius,
                                                                        std::size_t(polygon_sizes[k]), one_sided);
        c.diffuse_exact = disk_form_factor(c);
    } else {
        r = ltc::shade_line_light(P, N, V, roughness, one, one, one, c.p0, c.p1, c.radius);
        c.diffuse_exact = line_form_factor(c);
        const ltc::polygon_light_result<double> q = ltc::shade_tube_light(P, N, V, roughness, one, one, one, c.p0, c.p1, c.radius);
        c.ribbon = q.specular.x;
        c.ribbon_diffuse = q.diffuse.x;
    }
    c.ltc = r.specular.x;
    c.diffuse = r.diffuse.x;
}

/// The Monte Carlo side: `samples` iterations, seeds fixed by the configuration's index.
inline void evaluate_truth(config& c, std::size_t index, std::uint64_t samples) {
    const dvec3 V = view_of(c);
    const double alpha = roughnesses[c.rough] * roughnesses[c.rough];
    const ltc::brdf::ggx<double> ggx;
    gt::options opt;
    opt.samples = samples;
    opt.seed = 0x5A4E0000u + index;
    if (c.shape == sphere) {
        c.gt = gt::integrate_sphere(ggx, V, alpha, c.centre, c.radius, opt);
    } else if (c.shape == disk) {
        c.gt = gt::integrate_disk(ggx, V, alpha, c.centre, c.normal, c.radius, false, opt);
    } else {
        c.gt = gt::integrate_tube(ggx, V, alpha, c.p0, c.p1, c.radius, opt);
        opt.seed += 0x10000u;
        c.line = gt::integrate_line(ggx, V, alpha, c.p0, c.p1, opt);
        opt.seed += 0x10000u;
        c.tube_cosine = gt::integrate_tube(lambert{}, V, 0.0, c.p0, c.p1, c.radius, opt);
        // The ribbon's silhouette alone: the real GGX over the quad (integrate is two-sided).
        const ltc::tube_ribbon<double> q = ltc::make_tube_ribbon(dvec3(0), c.p0, c.p1, c.radius);
        opt.seed += 0x10000u;
        if (q.kind == ltc::tube_ribbon<double>::ribbon) c.ribbon_gt = gt::integrate(ggx, V, alpha, q.corner, 4, opt);
    }
}

}  // namespace shape_error_report
