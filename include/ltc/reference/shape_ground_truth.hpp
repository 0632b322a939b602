// ltc/reference/shape_ground_truth.hpp -- Monte Carlo ground truth for sphere, disk, tube and line
// lights: the integral of a BRDF model's rho(V, L) cos(theta_L) over the directions that the light
// covers, with its standard error (the polygon version is ltc/reference/ground_truth.hpp).
//
//   #include <ltc/reference/shape_ground_truth.hpp>
//   namespace gt = ltc::ground_truth;
//   gt::estimate s = gt::integrate_sphere(ltc::brdf::ggx<double>{}, V, alpha, centre, radius, opt);
//   gt::estimate d = gt::integrate_disk(model, V, alpha, centre, normal, radius, two_sided, opt);
//   gt::estimate t = gt::integrate_tube(model, V, alpha, p0, p1, radius, opt);
//   gt::estimate l = gt::integrate_line(model, V, alpha, p0, p1, opt);  // lim tube / (2 radius)
//
// Conventions as in ground_truth.hpp: double, the local shading frame (N = +z, V.z > 0, the
// shading point at the origin), the same options and estimate; directions with L.z <= 0 count 0.
// Degenerate input gives the zero estimate: radius <= 0, p0 = p1, a zero normal, a light entirely
// below the horizon, a one-sided disk seen from behind or edge-on, a line through the origin.
#pragma once

#include <ltc/config.hpp>

#include <ltc/detail/math.hpp>
#include <ltc/reference/ground_truth.hpp>  // options, estimate, heuristic, techniques
#include <ltc/reference/splitmix64.hpp>    // splitmix64
#include <ltc/shading/shading_frame.hpp>   // orthonormal_tangent (Duff et al. 2017)

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <initializer_list>

LTC_NAMESPACE_BEGIN
namespace ground_truth {
namespace shape_detail {

/// Runs iteration(rng) -> double in batches (ground_truth.hpp's Welford loop and adaptive mode).
template <typename Iteration>
estimate run(const options& opt, Iteration&& iteration) {
    splitmix64 rng(opt.seed);
    double mean = 0.0, m2 = 0.0;
    std::uint64_t n = 0;
    const bool adaptive = opt.target_relative_error > 0.0 || opt.target_absolute_error > 0.0;
    for (;;) {
        for (std::uint64_t it = 0, batch = glm::max<std::uint64_t>(opt.samples, 1); it < batch; ++it) {
            const double x = iteration(rng), d = x - mean;
            mean += d / static_cast<double>(++n);
            m2 += d * (x - mean);
        }
        const double var = n > 1 ? m2 / static_cast<double>(n - 1) : 0.0;
        const estimate e{mean, std::sqrt(var / static_cast<double>(n)), n};
        if (!adaptive || n >= opt.max_samples ||
            e.standard_error <= glm::max(opt.target_relative_error * std::abs(e.mean), opt.target_absolute_error))
            return e;
    }
}

/// MIS weight of the technique with density p against q (1 outside techniques::mis).
inline double weight(const options& opt, double p, double q) {
    if (opt.use != techniques::mis) return 1.0;
    if (opt.weighting == heuristic::power) {
        const double m = glm::max(p, q), a = p / m, b = q / m;  // scaled: no overflow of squares
        return a * a / (a * a + b * b);
    }
    return p / (p + q);
}

/// The MIS loop for a light with sample(u, L, pdf) -> bool (false: rejected) and
/// hit(L, pdf) -> bool (the ray meets the light; pdf: the light sampler's density there).
template <typename Model, typename Light>
estimate integrate_light(const Model& model, const glm::dvec3& V, double alpha, const Light& light,
                         const options& opt) {
    const bool use_brdf = opt.use != techniques::polygon_only;
    const bool use_light = opt.use != techniques::brdf_only;
    return run(opt, [&](splitmix64& rng) {
        double x = 0.0;
        if (use_brdf) {
            const glm::dvec3 L = model.sample(V, rng.uniform2(), alpha);
            const double p_b = model.pdf(V, L, alpha);
            double p_l = 0.0;
            if (p_b > 0.0 && L.z > 0.0 && light.hit(L, p_l)) {
                const double f = model.eval(V, L, alpha);
                if (f > 0.0) x += weight(opt, p_b, use_light ? p_l : 0.0) * f / p_b;
            }
        }
        if (use_light) {
            glm::dvec3 L(0.0);
            if (double p_l = 0.0; light.sample(rng.uniform2(), L, p_l) && p_l > 0.0 && L.z > 0.0) {
                const double f = model.eval(V, L, alpha);
                if (f > 0.0) x += weight(opt, p_l, use_brdf ? model.pdf(V, L, alpha) : 0.0) * f / p_l;
            }
        }
        return x;
    });
}

/// Uniform in the cone of directions within theta_max of a unit axis (the whole sphere inside).
struct sphere_cone {
    glm::dvec3 axis, t1, t2;
    double one_minus_cos;  // 1 - cos(theta_max), 2 for the whole sphere
    bool everywhere;
    double pdf() const { return 1.0 / (2.0 * pi<double>() * one_minus_cos); }
    bool sample(const glm::dvec2& u, glm::dvec3& L, double& p) const {
        const double t = u.x * one_minus_cos;  // 1 - cos(theta)
        const double sin_t = detail::safe_sqrt(t * (2.0 - t)), phi = detail::azimuth(u.y);
        L = sin_t * std::cos(phi) * t1 + sin_t * std::sin(phi) * t2 + (1.0 - t) * axis;
        p = pdf();
        return true;
    }
    bool hit(const glm::dvec3& L, double& p) const {
        const glm::dvec3 e = L - axis;  // |L - axis|^2 / 2 = 1 - cos: exact for tiny cones
        p = pdf();
        return everywhere || 0.5 * glm::dot(e, e) <= one_minus_cos;
    }
};

/// Uniform in the area of a disk (concentric mapping), in solid angle.
struct disk_area {
    glm::dvec3 centre, normal, t1, t2;
    double radius, area, n_dot_c;  // n_dot_c != 0: the origin is off the disk's plane
    bool sample(const glm::dvec2& u, glm::dvec3& L, double& p) const {
        // Shirley and Chiu 1997: [0, 1)^2 -> the unit disk, preserving area fractions.
        const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0, q = pi<double>() / 4.0;
        double r = 0.0, phi = 0.0;
        if (a * a > b * b) r = a, phi = q * (b / a);
        else if (b != 0.0) r = b, phi = 2.0 * q - q * (a / b);
        const glm::dvec3 x = centre + radius * r * (std::cos(phi) * t1 + std::sin(phi) * t2);
        const double dist = std::sqrt(glm::dot(x, x));
        L = x / dist;
        p = dist * dist * dist / (area * std::abs(n_dot_c));  // |cos at the light| = |n.c| / dist
        return true;
    }
    bool hit(const glm::dvec3& L, double& p) const {
        const double n_dot_l = glm::dot(normal, L);
        const double t = n_dot_c / n_dot_l;  // the ray's distance to the plane
        const glm::dvec3 off = t * L - centre;
        if (!(t > 0.0) || !(glm::dot(off, off) <= radius * radius)) return false;
        p = t * t / (area * std::abs(n_dot_l));
        return true;
    }
};

/// Uniform in the area of an open cylinder's lateral surface, first hits only, in solid angle.
struct tube_area {
    glm::dvec3 p0, axis, e1, e2, w_perp;  // w_perp: the origin's offset from the axis, -p0 perpendicular
    double radius, length, area, w_axial, c;  // w_axial = -p0.axis; c = |w_perp|^2 - radius^2
    /// Whether the ray point t L lies within the segment's span (axial coordinate in [0, length]).
    bool within(const glm::dvec3& L, double t) const {
        const double s = w_axial + t * glm::dot(L, axis);
        return s >= 0.0 && s <= length;
    }
    double density(const glm::dvec3& L, const glm::dvec3& n, double t) const {
        const double cos_l = std::abs(glm::dot(n, L));
        return cos_l > 0.0 ? t * t / (area * cos_l) : 0.0;
    }
    bool sample(const glm::dvec2& u, glm::dvec3& L, double& p) const {
        const double phi = detail::azimuth(u.y);
        const glm::dvec3 n = std::cos(phi) * e1 + std::sin(phi) * e2;
        const glm::dvec3 x = p0 + (u.x * length) * axis + radius * n;
        const double dist = std::sqrt(glm::dot(x, x));
        L = x / dist;
        if (glm::dot(n, L) > 0.0 && c > 0.0) {  // an exit point, the origin outside: entry at t > 0
            const glm::dvec3 l_perp = L - glm::dot(L, axis) * axis;
            const double t_entry = c / (glm::dot(l_perp, l_perp) * dist);  // product of the roots
            if (within(L, t_entry)) return false;                          // hidden by the entry
        }
        p = density(L, n, dist);
        return p > 0.0;
    }
    bool hit(const glm::dvec3& L, double& p) const {
        // |w_perp + t l_perp|^2 = r^2: a t^2 + 2 b t + c = 0, roots by the stable formula.
        const glm::dvec3 l_perp = L - glm::dot(L, axis) * axis;
        const double a = glm::dot(l_perp, l_perp), b = glm::dot(w_perp, l_perp);
        const double disc = b * b - a * c;
        if (!(a > 0.0) || disc < 0.0) return false;  // parallel to the axis, or a miss
        const double q = -(b + std::copysign(std::sqrt(disc), b));
        if (q == 0.0) return false;  // the origin on the surface (c = 0), grazing
        for (const double t : {glm::min(q / a, c / q), glm::max(q / a, c / q)})
            if (t > 0.0 && within(L, t)) {
                p = density(L, (w_perp + t * l_perp) / radius, t);
                return p > 0.0;
            }
        return false;
    }
};

}  // namespace shape_detail

/// Monte Carlo estimate of int model.eval(V, L, alpha) dL over the directions (L.z > 0) of the
/// sphere of the given centre and radius (inside: the full upper hemisphere).
///
/// Conventions as in ground_truth.hpp: the same options (seed, heuristic, adaptive batches; the
/// light sampler plays the part of the polygon sampler, so techniques::polygon_only means "light
/// sampling only") and the same estimate. Unlike integrate(), directions with L.z <= 0 contribute
/// 0 whatever the model returns there (a light partly below the horizon is clipped).
///
/// Estimator (sphere, disk, tube): per iteration one BRDF sample (model.sample, density model.pdf)
/// and one light sample, combined by MIS (Veach and Guibas 1995, one sample per technique). A BRDF
/// sample counts when its ray meets the light; the light's density is taken at the ray's *first*
/// intersection. Standard error: as in ground_truth.hpp (Welford; the same caveat).
///
/// The sphere's sampler: uniform in the cone it subtends, density 1 / (2 pi (1 - cos theta_max)),
/// with 1 - cos = sin^2 / (1 + cos) and the membership test |L - axis|^2 / 2 <= 1 - cos (accurate
/// for tiny cones). Shading point inside or on the sphere: every direction is covered, the sampler
/// is uniform on the sphere (1 / (4 pi)) and the result is the BRDF's integral over the upper
/// hemisphere (its directional albedo). Zero estimate: radius <= 0, or the sphere entirely below
/// the horizon.
template <typename Model>
estimate integrate_sphere(const Model& model, const glm::dvec3& V, double alpha, const glm::dvec3& centre,
                          double radius, const options& opt = {}) {
    if (!(radius > 0.0)) return {};
    const double d = std::sqrt(glm::dot(centre, centre));
    const bool everywhere = !(d > radius), below = centre.z + radius <= 0.0;
    if (below && !everywhere) return {};  // entirely below the horizon
    const double s = everywhere ? 1.0 : radius / d;  // sin(theta_max); 1 - cos = sin^2 / (1 + cos)
    const double omc = everywhere ? 2.0 : s * s / (1.0 + std::sqrt((1.0 - s) * (1.0 + s)));
    const glm::dvec3 a = d > 0.0 ? centre / d : glm::dvec3(0, 0, 1), t1 = orthonormal_tangent(a);
    const shape_detail::sphere_cone cone{a, t1, glm::cross(a, t1), omc, everywhere};
    return shape_detail::integrate_light(model, V, alpha, cone, opt);
}

/// Monte Carlo estimate of int model.eval(V, L, alpha) dL over the directions (L.z > 0) of the
/// disk of the given centre, normal (any length) and radius; a one-sided disk emits towards +normal.
/// Estimator: integrate_sphere's, the light sampler uniform in area (Shirley and Chiu's concentric
/// mapping), in solid angle dist^2 / (area |cos at the light|). Zero estimate: radius <= 0, a zero
/// normal, a disk seen edge-on, or a one-sided disk seen from behind.
template <typename Model>
estimate integrate_disk(const Model& model, const glm::dvec3& V, double alpha, const glm::dvec3& centre,
                        const glm::dvec3& normal, double radius, bool two_sided, const options& opt = {}) {
    const double len = std::sqrt(glm::dot(normal, normal));
    if (!(radius > 0.0) || !(len > 0.0)) return {};
    const glm::dvec3 n = normal / len, t1 = orthonormal_tangent(n);
    const double n_dot_c = glm::dot(n, centre);
    if (n_dot_c == 0.0 || (!two_sided && n_dot_c > 0.0)) return {};  // edge-on, or its back
    const double area = pi<double>() * radius * radius;
    const shape_detail::disk_area disk{centre, n, t1, glm::cross(n, t1), radius, area, n_dot_c};
    return shape_detail::integrate_light(model, V, alpha, disk, opt);
}

/// Monte Carlo estimate of int model.eval(V, L, alpha) dL over the directions (L.z > 0) whose ray
/// meets the open cylinder (no end caps) of the given radius around the segment p0-p1.
/// Estimator: integrate_sphere's, both faces emitting: the directions whose ray meets the lateral
/// surface (through an open end too). Uniform area sampling of the whole lateral surface; a point
/// that is not the first hit of its ray is rejected (contributes 0), so a direction's density is
/// dist^2 / (area |cos|) at its first hit. Visibility without tolerance: an entry point of the
/// infinite cylinder is a first hit; an exit point is hidden iff the entry root (product of the
/// roots c / a) is at t > 0 within the segment's span. Zero estimate: radius <= 0, p0 = p1, or the
/// tube entirely below the horizon; a shading point exactly on the tube's surface is unsupported.
template <typename Model>
estimate integrate_tube(const Model& model, const glm::dvec3& V, double alpha, const glm::dvec3& p0,
                        const glm::dvec3& p1, double radius, const options& opt = {}) {
    const glm::dvec3 span = p1 - p0;
    const double length = std::sqrt(glm::dot(span, span));
    if (!(radius > 0.0) || !(length > 0.0) || glm::max(p0.z, p1.z) + radius <= 0.0) return {};
    const glm::dvec3 a = span / length, e1 = orthonormal_tangent(a);
    const double w_axial = -glm::dot(p0, a);
    const glm::dvec3 w_perp = -p0 - w_axial * a;
    const shape_detail::tube_area tube{p0,     a,      e1, glm::cross(a, e1), w_perp, radius,
                                       length, 2.0 * pi<double>() * radius * length, w_axial,
                                       glm::dot(w_perp, w_perp) - radius * radius};
    return shape_detail::integrate_light(model, V, alpha, tube, opt);
}

/// Monte Carlo estimate of the thin-line integral lim_{r->0} integrate_tube(..., r) / (2r) =
/// int_{p0}^{p1} model.eval(V, x/|x|, alpha) d/|x|^3 dl, in 1/length.
///
/// Light sampling only (opt.use and opt.weighting are ignored: BRDF samples hit a line with
/// probability 0). A cylinder of radius r is 2r/|x| wide at its axis point x (across the plane of
/// the origin and the axis), and an axis element dl spans dl sin(phi)/|x| in that plane, phi the
/// angle between the axis and x, sin(phi) = d/|x| (d: the distance from the origin to the axis
/// line). So dw = 2r d/|x|^3 dl + O(r^2) and
///   I_line = lim_{r->0} integrate_tube / (2r) = int_{p0}^{p1} f(x/|x|) d/|x|^3 dl   (1/length).
/// With the foot point d n (n unit), tangent t, x = d n + l t and s = l/|x| = sin(theta):
/// dl = |x|^3/d^2 ds, so I_line = (1/d) int_{s_0}^{s_1} f(sqrt(1 - s^2) n + s t) ds, estimated with
/// s uniform (weight (s_1 - s_0)/d) after clipping the segment to z >= 0 (x.z is linear in l: the
/// same line). s_1 - s_0 = d^2 L (l_0 + l_1) / ((l_1 |x_0| + l_0 |x_1|) |x_0| |x_1|) when
/// l_0 l_1 > 0 (no cancellation for a segment nearly pointing at the origin). Zero estimate:
/// p0 = p1, the segment entirely below the horizon, or its axis passing through the origin
/// (edge-on: the limit for a segment pointing at the origin, a convention for one through it, as
/// in ltc/core/line_integral.hpp).
template <typename Model>
estimate integrate_line(const Model& model, const glm::dvec3& V, double alpha, glm::dvec3 p0, glm::dvec3 p1,
                        const options& opt = {}) {
    const glm::dvec3 span = p1 - p0;
    const double length = std::sqrt(glm::dot(span, span));
    if (!(length > 0.0) || glm::max(p0.z, p1.z) <= 0.0) return {};
    const glm::dvec3 t = span / length;
    const glm::dvec3 foot = p0 - glm::dot(p0, t) * t;  // d n
    const double d = std::sqrt(glm::dot(foot, foot));
    if (!(d > 0.0)) return {};  // the axis through the origin: seen edge-on
    const glm::dvec3 n = foot / d;
    if (p0.z < 0.0) p0 += (p0.z / (p0.z - p1.z)) * span;  // clip to the horizon (same line)
    if (p1.z < 0.0) p1 -= (p1.z / (p1.z - p0.z)) * span;
    const double l0 = glm::dot(p0, t), l1 = glm::dot(p1, t);
    const double r0 = std::sqrt(glm::dot(p0, p0)), r1 = std::sqrt(glm::dot(p1, p1));
    const double s0 = l0 / r0, s1 = l1 / r1;
    const double ds = l0 * l1 > 0.0 ? d * d * (l1 - l0) * (l0 + l1) / ((l1 * r0 + l0 * r1) * r0 * r1) : s1 - s0;
    const double w = ds / d;
    return shape_detail::run(opt, [&](splitmix64& rng) {
        const double s = s0 + rng.uniform() * ds;
        const glm::dvec3 L = detail::safe_sqrt((1.0 - s) * (1.0 + s)) * n + s * t;
        return L.z > 0.0 ? w * model.eval(V, L, alpha) : 0.0;
    });
}

}  // namespace ground_truth
LTC_NAMESPACE_END
