// ltc/fitting/integral_objective.hpp -- an opt-in objective for the fit (options::goal =
// objective::integrals or objective::combined): instead of the paper's L3 distance between the
// lobes (section 4), the relative error of the *integrals* that shading computes, over a fixed
// family of spherical polygons around and off the lobe; ltc/fitting/fit_integrals.hpp minimizes it.
//
//   auto targets = ltc::fit::make_integral_targets<ltc::brdf::ggx>(V, alpha, axis, magnitude,
//                                                                  ltc::fit::integral_family::spiral());
//   double loss = ltc::fit::integral_loss(targets, m_inv, magnitude);
//
//   loss = (1/K) sum_k ((m I_k - G_k) / (G_k + floor m_0))^2,   I_k = int_{P_k} D (eq. 3), G_k = int_{P_k} f
//
// Conventions: double, the local shading frame (f symmetric in y); P_k regular spherical hexagons
// (polygon_family), G_k by a deterministic quadrature (make_integral_targets). Degenerate cases:
// polygons with G_k below significance_threshold m_0 are dropped; the loss of none is 0.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/brdf/schlick.hpp>
#include <ltc/fitting/ltc_parameters.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

LTC_NAMESPACE_BEGIN
namespace fit {

/// One hexagon of the family: its vertices, its centre and tangent frame (gnomonic projection),
/// and its inward edge normals (L is inside iff dot(L, n_k) >= 0 for all k, and L.c > 0).
struct family_polygon {
    std::array<glm::dvec3, 6> vertices;
    std::array<glm::dvec3, 6> edge_normals;
    glm::dvec3 centre{0, 0, 1}, e1{1, 0, 0}, e2{0, 1, 0};
    double planar_radius = 0;  ///< tan(r): circumradius of the gnomonic hexagon
    double planar_area = 0;    ///< (3 sqrt(3) / 2) tan(r)^2

    bool contains(const glm::dvec3& L) const {
        if (!(glm::dot(L, centre) > 0)) return false;
        for (const glm::dvec3& n : edge_normals)
            if (glm::dot(L, n) < 0) return false;
        return true;
    }
    /// Density on the sphere of uniform sampling of the planar hexagon (0 outside).
    double pdf(const glm::dvec3& L) const {
        if (!contains(L)) return 0.0;
        const double c = glm::dot(L, centre);
        return 1.0 / (planar_area * c * c * c);
    }
};

/// A hexagon of angular circumradius r centred on the unit direction c.
inline family_polygon make_hexagon(const glm::dvec3& c, double r) {
    family_polygon p;
    p.centre = c;
    const glm::dvec3 t = std::abs(c.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    p.e1 = normalize_or_zero(glm::cross(t, c));
    p.e2 = glm::cross(c, p.e1);
    p.planar_radius = std::tan(r);
    p.planar_area = 1.5 * std::sqrt(3.0) * p.planar_radius * p.planar_radius;
    for (int k = 0; k < 6; ++k) {
        const double phi = 0.1 + 2.0 * pi<double>() * k / 6.0;
        p.vertices[std::size_t(k)] = c * std::cos(r) + (std::cos(phi) * p.e1 + std::sin(phi) * p.e2) * std::sin(r);
    }
    for (std::size_t k = 0; k < 6; ++k) {
        glm::dvec3 n = glm::cross(p.vertices[k], p.vertices[(k + 1) % 6]);
        if (glm::dot(n, c) < 0) n = -n;
        p.edge_normals[k] = n;
    }
    return p;
}

/// What covers the hemisphere besides the lobe's hexagons (polygon_family): the rings of radius
/// 0.25 and 0.6 rad, or the spiral of 16 centres with 3 radii.
enum class hemisphere_covering { rings, spiral };

/// Polygons whose GGX integral is below this fraction of the magnitude are dropped from the
/// targets (the error report's significance threshold).
inline constexpr double significance_threshold = 1e-3;

/// The GGX quadrature's default sizes (make_integral_targets): n_b x n_b BRDF samples, 6 m x m
/// samples per polygon.
inline constexpr int default_brdf_samples = 64;
inline constexpr int default_polygon_samples = 8;

/// What a fit's integral targets are made of: the covering and the loss's floor (a fraction of
/// the node's magnitude). The defaults are the rings'.
struct integral_family {
    hemisphere_covering covering = hemisphere_covering::rings;
    double floor = 0.01;

    /// The one-lobe `integrals` objective's and the two-LTC table's: the rings, a floor of 0.01.
    static constexpr integral_family rings() { return {}; }
    /// The LTC-and-cosine table's: the spiral, a floor at the significance threshold. The default
    /// quadrature's error on its hexagons (its lowest ones straddle the horizon) and on the
    /// rings' is bounded by tests/test_fit_objective.cpp; docs/design_notes.md: the finer
    /// quadrature tried.
    static constexpr integral_family spiral() { return {hemisphere_covering::spiral, significance_threshold}; }
};

/// The family for a lobe of average direction `axis` (unit, in the xz-plane) and roughness
/// alpha: the lobe's hexagons, then the covering's; per node, the same for every candidate M.
/// Regular spherical hexagons, vertices at angular radius r from their centre c, first vertex at
/// phase 0.1 rad, edges on great circles:
///   lobe       radii r_j = r0 (1.2 / r0)^(j / 4), j = 0..4, r0 = clamp(0.7 alpha, 5e-5, 0.3):
///              from about half the lobe's width (the GGX lobe's half width at half maximum is
///              about 1.3 alpha in L) to 1.2 rad, geometrically spaced. Centred on the lobe's
///              average direction A (the fit's axis, ltc/fitting/moments.hpp) for every r_j, and
///              for j < 4 also centred 2 r_j away from A towards the normal, towards the horizon
///              and across the plane of incidence (+y): 5 + 12 hexagons;
///   hemisphere a fixed covering of the upper half-hemisphere y >= 0 (f is symmetric in y):
///              radius 0.25 rad at elevations 4, 15, 35, 60 deg and azimuths 22.5 + 45 k deg,
///              k = 0..3, and one at elevation 80 deg, azimuth 22.5 deg: 17 hexagons (the lowest
///              ring straddles the horizon); and 8 larger ones, radius 0.6 rad, at elevations
///              12 and 45 deg, azimuths 0, 60, 120, 180 deg (lights of the size that matters
///              most);
///   spiral     (hemisphere_covering::spiral, the LTC-and-cosine table's: integral_family::spiral())
///              instead of the rings above: lights of every size anywhere, the faint tails
///              included, where the cosine's share of a two-part lobe shows: 16 centres of the
///              golden-angle spiral over the whole upper hemisphere, uniform in solid angle
///              (z_i = (i + 1/2) / 16, azimuth i 137.508 deg), each mirrored into y >= 0 (f is
///              symmetric in y, so a hexagon at the mirrored centre stands for one at the
///              original; mirroring rather than folding the azimuths into [0, 180) keeps the
///              centres spread: no direction farther than 0.44 rad from its nearest centre,
///              tests/test_fit_objective.cpp), with hexagons of radius 0.15, 0.45 and 0.9 rad on
///              each: 48 hexagons. Its lowest hexagons straddle the horizon in the tails, where
///              the quadrature is least accurate (integral_family).
/// This family is deliberately not the grid of tools/ggx_error_report (rectangles, triangles,
/// pentagons at fixed placements and angular radii whatever the roughness), so that the report
/// measures generalization (docs/design_notes.md: the nearest placements of the two).
inline std::vector<family_polygon> polygon_family(const glm::dvec3& axis, double alpha,
                                                  hemisphere_covering covering = hemisphere_covering::rings) {
    std::vector<family_polygon> family;
    const double r0 = std::min(std::max(0.7 * alpha, 5e-5), 0.3);
    // Tilting in the plane of incidence: rotation about y (positive angle: towards +x).
    const auto tilt_xz = [](const glm::dvec3& d, double a) {
        return glm::dvec3(d.x * std::cos(a) + d.z * std::sin(a), d.y, -d.x * std::sin(a) + d.z * std::cos(a));
    };
    // Towards the normal from A (A.x <= 0): rotate towards +x; towards the horizon: towards -x.
    // (At normal incidence A = +z and the two are mirror images: both kept, the fit is isotropic.)
    const glm::dvec3 across(0, 1, 0);
    const auto off_axis = [&](double d, double az) {  // d from A, az = 0 towards the normal, 90 across
        const glm::dvec3 up = normalize_or_zero(tilt_xz(axis, 0.5 * pi<double>()));
        const glm::dvec3 dir = std::cos(az) * up + std::sin(az) * across;
        return normalize_or_zero(axis * std::cos(d) + dir * std::sin(d));
    };
    for (int j = 0; j < 5; ++j) {
        const double r = r0 * std::pow(1.2 / r0, j / 4.0);
        family.push_back(make_hexagon(axis, r));
        if (j == 4) break;  // the largest: centred only
        family.push_back(make_hexagon(off_axis(2 * r, 0.0), r));
        family.push_back(make_hexagon(off_axis(2 * r, pi<double>()), r));
        family.push_back(make_hexagon(off_axis(2 * r, 0.5 * pi<double>()), r));
    }
    // A fixed covering of the upper half-hemisphere (the lobe is symmetric in y).
    const auto at = [](double el_deg, double az_deg) {
        const double e = el_deg * pi<double>() / 180.0, a = az_deg * pi<double>() / 180.0;
        return glm::dvec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
    };
    if (covering == hemisphere_covering::spiral) {
        constexpr int centres = 16;
        for (int i = 0; i < centres; ++i) {
            const double el = std::asin((i + 0.5) / centres) * 180.0 / pi<double>();
            double az = std::fmod(i * 137.50776405003785, 360.0);  // the golden angle
            if (az > 180.0) az = 360.0 - az;                         // mirrored into y >= 0
            for (double r : {0.15, 0.45, 0.9}) family.push_back(make_hexagon(at(el, az), r));
        }
        return family;
    }
    // The rings: radius 0.25 rad at elevations 4, 15, 35, 60 deg, azimuths 22.5 + 45 k deg, and
    // at 80 deg (the lowest ring straddles the horizon); radius 0.6 rad at elevations 12 and 45
    // deg, azimuths 60 k deg.
    for (double el : {4.0, 15.0, 35.0, 60.0})
        for (int k = 0; k < 4; ++k) family.push_back(make_hexagon(at(el, 22.5 + 45.0 * k), 0.25));
    family.push_back(make_hexagon(at(80.0, 22.5), 0.25));
    for (double el : {12.0, 45.0})
        for (int k = 0; k < 4; ++k) family.push_back(make_hexagon(at(el, 60.0 * k), 0.6));
    return family;
}

/// The family and its GGX integrals G_k (make_integral_targets), the polygons with G_k below the
/// significance threshold removed.
struct integral_targets {
    std::vector<family_polygon> polygons;
    std::vector<double> ggx;
    double magnitude = 0;
    double floor = integral_family{}.floor;  ///< the loss's floor, a fraction of the magnitude
};

namespace detail {

/// The quadrature's sums G_k over `family` (make_integral_targets) of f = Brdf::eval, and, with `fresnel`
/// not null, of f (1 - V.H)^5 (brdf::schlick_weight, the Fresnel part) from the same samples in
/// the same pass: each sum is the one make_integral_targets gives for Brdf, or for
/// brdf::fresnel_part<Brdf>, bit for bit. Alpha is the BRDF's parameter (double, or
/// brdf::anisotropic_alpha<double> for ltc/fitting/fit_anisotropic.hpp).
template <template <typename> class Brdf, typename Alpha>
void family_integrals(const glm::dvec3& V, const Alpha& alpha, const std::vector<family_polygon>& family, int n_b, int m,
                      std::vector<double>& g, std::vector<double>* fresnel) {
    using B = Brdf<double>;
    const double N_b = double(n_b) * double(n_b), N_p = 6.0 * double(m) * double(m);
    g.assign(family.size(), 0.0);
    if (fresnel) fresnel->assign(family.size(), 0.0);
    // f_fresnel = f (1 - V.H)^5, once per sample; f > 0 and finite, so it is finite and >= 0.
    const auto add = [&](std::size_t k, double f, double f_fresnel, double denominator) {
        g[k] += f / denominator;
        if (fresnel) (*fresnel)[k] += f_fresnel / denominator;
    };
    const auto fresnel_part = [&](const glm::dvec3& L, double f) { return fresnel ? f * brdf::schlick_weight(V, L) : 0.0; };
    // Technique 1: the BRDF's sampler, shared by all polygons.
    for (int j = 0; j < n_b; ++j)
        for (int i = 0; i < n_b; ++i) {
            const glm::dvec3 L = B::sample(V, glm::dvec2((i + 0.5) / n_b, (j + 0.5) / n_b), alpha);
            if (!(L.z > 0)) continue;
            const double f = B::eval(V, L, alpha);
            const double pb = B::pdf(V, L, alpha);
            if (!(f > 0) || !std::isfinite(f)) continue;
            const double ff = fresnel_part(L, f);
            for (std::size_t k = 0; k < family.size(); ++k) {
                const double pk = family[k].pdf(L);
                if (pk > 0) add(k, f, ff, N_b * pb + N_p * pk);
            }
        }
    // Technique 2: uniform in each polygon's gnomonic projection (6 triangles (0, P_k, P_k+1)).
    for (std::size_t k = 0; k < family.size(); ++k) {
        const family_polygon& p = family[k];
        for (int t = 0; t < 6; ++t) {
            const double a0 = 0.1 + 2.0 * pi<double>() * t / 6.0, a1 = a0 + 2.0 * pi<double>() / 6.0;
            const glm::dvec2 P0 = p.planar_radius * glm::dvec2(std::cos(a0), std::sin(a0));
            const glm::dvec2 P1 = p.planar_radius * glm::dvec2(std::cos(a1), std::sin(a1));
            for (int j = 0; j < m; ++j)
                for (int i = 0; i < m; ++i) {
                    const double s = std::sqrt((i + 0.5) / m), v = (j + 0.5) / m;
                    const glm::dvec2 q = s * ((1.0 - v) * P0 + v * P1);
                    const glm::dvec3 L = normalize_or_zero(p.centre + q.x * p.e1 + q.y * p.e2);
                    if (!(L.z > 0)) continue;
                    const double f = B::eval(V, L, alpha);
                    if (!(f > 0) || !std::isfinite(f)) continue;
                    const double c = glm::dot(L, p.centre);
                    const double pk = 1.0 / (p.planar_area * c * c * c);
                    add(k, f, fresnel_part(L, f), N_b * B::pdf(V, L, alpha) + N_p * pk);
                }
        }
    }
}

/// The targets: the polygons of `family` whose sum g_k is at least the significance threshold
/// times `magnitude` (and finite), with their sums, the magnitude and the loss's floor.
inline integral_targets significant_targets(const std::vector<family_polygon>& family, const std::vector<double>& g,
                                            double magnitude, double floor) {
    integral_targets r;
    r.magnitude = magnitude;
    r.floor = floor;
    for (std::size_t k = 0; k < family.size(); ++k)
        if (g[k] >= significance_threshold * magnitude && std::isfinite(g[k])) {
            r.polygons.push_back(family[k]);
            r.ggx.push_back(g[k]);
        }
    return r;
}

}  // namespace detail

/// For the view V, roughness alpha, the lobe's average direction `axis` and magnitude: the
/// polygons of `which` (its covering; its floor goes into the targets), n_b x n_b BRDF samples,
/// 6 m x m samples per polygon (by default 64, 8; the accuracy and cost of other sizes:
/// docs/design_notes.md).
///
/// Both integrals are deterministic. The LTC's in closed form, with the horizon clipped in LTC
/// space as horizon_clipping::ltc_space does (transformed<clamped_cosine<double>>::integrate).
/// GGX's once per node, by a two-technique quadrature with the balance heuristic: n_b x n_b
/// midpoint samples through Brdf::sample (shared by all polygons), and, per polygon, 6 m x m
/// midpoint samples uniform in its gnomonic projection (the planar hexagon tangent at c, cut
/// into 6 triangles; density on the sphere 1 / (A (L.c)^3), A the planar area):
///   G_k = sum_{brdf i, L_i in P_k} f_i / (N_b p_b + N_k p_k) + sum_{poly j} f_j / (N_b p_b + N_k p_k).
/// Polygons with G_k < 1e-3 magnitude are dropped (the error report's significance threshold).
template <template <typename> class Brdf>
integral_targets make_integral_targets(const glm::dvec3& V, double alpha, const glm::dvec3& axis, double magnitude,
                                       int n_b = default_brdf_samples, int m = default_polygon_samples,
                                       const integral_family& which = integral_family::rings()) {
    const std::vector<family_polygon> family = polygon_family(axis, alpha, which.covering);
    std::vector<double> g;
    detail::family_integrals<Brdf>(V, alpha, family, n_b, m, g, nullptr);
    return detail::significant_targets(family, g, magnitude, which.floor);
}

/// The targets of f (first) and of its Fresnel part f (1 - V.H)^5 (second: magnitude `fresnel`,
/// the integral of the Fresnel part over the hemisphere, in the place of the magnitude) over the
/// same family, from one pass of the quadrature (the two-lobe fits' split of the Fresnel term,
/// ltc/fitting/fit_two_lobes.hpp): each the same bits as make_integral_targets gives for Brdf and
/// for brdf::fresnel_part<Brdf>, at about the cost of one. The same samples give the integrals
/// of f (1 - V.H)^5 in place of f; their error against the ground truth on both families'
/// hexagons is bounded by tests/test_fit_objective.cpp.
template <template <typename> class Brdf>
std::pair<integral_targets, integral_targets> make_integral_targets_with_fresnel(
    const glm::dvec3& V, double alpha, const glm::dvec3& axis, double magnitude, double fresnel,
    const integral_family& which, int n_b = default_brdf_samples, int m = default_polygon_samples) {
    const std::vector<family_polygon> family = polygon_family(axis, alpha, which.covering);
    std::vector<double> g, g_fresnel;
    detail::family_integrals<Brdf>(V, alpha, family, n_b, m, g, &g_fresnel);
    return {detail::significant_targets(family, g, magnitude, which.floor),
            detail::significant_targets(family, g_fresnel, fresnel, which.floor)};
}

/// The targets of `which` with the default quadrature: what the fits use.
template <template <typename> class Brdf>
integral_targets make_integral_targets(const glm::dvec3& V, double alpha, const glm::dvec3& axis, double magnitude,
                                       const integral_family& which) {
    return make_integral_targets<Brdf>(V, alpha, axis, magnitude, default_brdf_samples, default_polygon_samples, which);
}

/// The LTC integrals I_k of the distribution of m_inv (any scale, ltc_space clipping), their edge
/// terms evaluated by Policy (ltc/core/edge_policy.hpp).
template <typename Policy = edge_policy::exact>
void ltc_integrals(const integral_targets& t, const glm::dmat3& m_inv, double* out) {
    const auto D = transformed<clamped_cosine<double, Policy>>::from_inverse(m_inv);
    for (std::size_t k = 0; k < t.polygons.size(); ++k) out[k] = D.integrate(t.polygons[k].vertices.data(), 6);
}

/// (1/K) sum_k ((magnitude I_k - G_k) / (G_k + floor m_0))^2 (0 when no polygon is
/// significant; floor = t.floor, m_0 = t.magnitude): the relative error, softened for the faint
/// polygons. The floor f is a fraction of the magnitude (the albedo) in the denominator. With the
/// rings f = 0.01: without a floor the faint tails (which a single lobe cannot follow everywhere)
/// outvote the few polygons on the peak; squared rather than absolute for a smooth objective.
/// With the spiral the floor is the significance threshold, 1e-3 m_0: the tails count as relative
/// errors, as the error report counts them, and a lobe of two parts can follow them.
inline double integral_loss(const integral_targets& t, const glm::dmat3& m_inv, double magnitude) {
    const auto D = transformed<clamped_cosine<double>>::from_inverse(m_inv);
    const double floor = t.floor * t.magnitude;
    double s = 0;
    for (std::size_t k = 0; k < t.polygons.size(); ++k) {
        const double e = (magnitude * D.integrate(t.polygons[k].vertices.data(), 6) - t.ggx[k]) / (t.ggx[k] + floor);
        s += e * e;
    }
    return t.polygons.empty() ? 0.0 : s / double(t.polygons.size());
}

}  // namespace fit
LTC_NAMESPACE_END
