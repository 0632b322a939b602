// ltc/reference/spherical_polygon.hpp -- a polygon light as a set of directions, for the Monte
// Carlo ground truth (ltc/reference/ground_truth.hpp): uniform sampling in solid angle, its
// density, and the winding number that says which directions the polygon covers.
//
//   const ltc::ground_truth::spherical_polygon poly(vertices, n);
//   glm::dvec3 w = poly.sample(u);    // u in [0, 1)^3; density poly.pdf(w)
//
// Conventions: double, directions seen from the origin; a fan from vertex 0, each triangle chosen
// by solid angle (Van Oosterom and Strackee 1983) and sampled by Arvo's method (Arvo 1995).
// Degenerate cases: non-convex polygons are handled exactly (spherical_polygon); a polygon of no
// solid angle is empty().
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/solid_angle.hpp>  // triangle_solid_angle
#include <ltc/detail/math.hpp>
#include <ltc/reference/spherical_triangle.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

LTC_NAMESPACE_BEGIN
namespace ground_truth {

/// A spherical polygon seen from the origin, triangulated as a fan from vertex 0: uniform
/// sampling, its density and the winding number.
///
/// Polygon sampling. The polygon is triangulated as a fan from vertex 0; each fan triangle is
/// the projection of a planar triangle that does not contain the origin, so it lies in an open
/// hemisphere. A triangle is chosen with probability proportional to its solid angle (Van
/// Oosterom and Strackee 1983) and sampled uniformly by Arvo's method (Arvo 1995, "Stratified
/// sampling of spherical triangles", SIGGRAPH; in the arrangement of pbrt-v4's
/// SampleSphericalTriangle). Non-convex polygons are handled exactly: fan triangles whose
/// orientation opposes the polygon's (they cancel parts of other triangles) are never sampled,
/// the density at w is (number of same-orientation fan triangles containing w) / (their total
/// solid angle), and a sample that lands where the winding number is 0 contributes 0. For a
/// convex polygon this is exactly uniform: density 1 / Omega inside.
class spherical_polygon {
  public:
    /// vertices[0..n): a simple planar polygon (any scale, any winding) that does not contain
    /// the origin in its plane. n < 3 or zero solid angle gives an empty polygon.
    spherical_polygon(const glm::dvec3* vertices, std::size_t n) {
        if (n < 3) return;
        std::vector<glm::dvec3> u(n);
        for (std::size_t i = 0; i < n; ++i) {
            u[i] = detail::safe_normalize(vertices[i]);
            if (u[i] == glm::dvec3(0.0)) return;  // vertex at the origin: seen edge-on
        }
        double total = 0.0;
        for (std::size_t i = 1; i + 1 < n; ++i) {
            tris_.push_back(make_triangle(u[0], u[i], u[i + 1]));
            total += tris_.back().omega;
        }
        signed_solid_angle_ = total;
        // Same-orientation triangles are the ones we sample.
        double acc = 0.0;
        for (auto& t : tris_) {
            t.sampled = total != 0.0 && t.omega * total > 0.0;
            if (t.sampled) acc += std::abs(t.omega);
            cdf_.push_back(acc);
        }
        sampled_solid_angle_ = acc;
    }

    /// Signed solid angle (positive for clockwise vertices as seen from the origin).
    double signed_solid_angle() const { return signed_solid_angle_; }
    double solid_angle() const { return std::abs(signed_solid_angle_); }
    bool empty() const { return !(sampled_solid_angle_ > 0.0); }

    /// Winding number of the boundary around w (unit): +-1 inside a simple polygon, 0 outside.
    int winding(const glm::dvec3& w) const {
        int k = 0;
        for (const auto& t : tris_)
            if (t.omega != 0.0 && inside(t, w)) k += t.omega > 0.0 ? 1 : -1;
        return k;
    }
    bool contains(const glm::dvec3& w) const { return winding(w) != 0; }

    /// Density of sample() at the unit direction w, per steradian.
    double pdf(const glm::dvec3& w) const {
        if (empty()) return 0.0;
        int count = 0;
        for (const auto& t : tris_)
            if (t.sampled && inside(t, w)) ++count;
        return count / sampled_solid_angle_;
    }

    /// contains(w) and pdf(w) in one pass over the triangles.
    void classify(const glm::dvec3& w, bool& is_inside, double& density) const {
        int k = 0, count = 0;
        for (const auto& t : tris_) {
            if (t.omega == 0.0 || !inside(t, w)) continue;
            k += t.omega > 0.0 ? 1 : -1;
            count += t.sampled;
        }
        is_inside = k != 0;
        density = empty() ? 0.0 : count / sampled_solid_angle_;
    }

    /// A direction with density pdf(); u in [0, 1)^3 (u.x picks the triangle). Precondition:
    /// !empty().
    glm::dvec3 sample(const glm::dvec3& u) const {
        const double target = u.x * sampled_solid_angle_;
        std::size_t k = static_cast<std::size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin());
        if (k >= tris_.size()) k = tris_.size() - 1;
        while (k > 0 && !tris_[k].sampled) --k;  // target on a flat step of the cdf
        return tris_[k].sampler.sample(glm::dvec2(u.y, u.z));
    }

  private:
    struct triangle {
        glm::dvec3 a, b, c;
        double omega;                // signed solid angle
        bool sampled;                // same orientation as the polygon
        glm::dvec3 n_ab, n_bc, n_ca;  // inward normals of its great circles
        spherical_triangle_sampler sampler;
    };

    static triangle make_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
        const double omega = triangle_solid_angle(a, b, c);
        const double s = omega > 0.0 ? 1.0 : -1.0;
        // Member by member: nvcc's front end mis-parses brace elision around glm vectors here.
        triangle t{a, b, c, omega, false, s * glm::cross(a, b), s * glm::cross(b, c), s * glm::cross(c, a),
                   spherical_triangle_sampler(a, b, c)};
        return t;
    }

    // Inside the spherical triangle: on the inner side of its three great circles (the triangle
    // lies in an open hemisphere, so this is the triangle itself).
    static bool inside(const triangle& t, const glm::dvec3& w) {
        return glm::dot(w, t.n_ab) >= 0.0 && glm::dot(w, t.n_bc) >= 0.0 && glm::dot(w, t.n_ca) >= 0.0;
    }

    std::vector<triangle> tris_;
    std::vector<double> cdf_;
    double signed_solid_angle_ = 0.0;
    double sampled_solid_angle_ = 0.0;
};

}  // namespace ground_truth
LTC_NAMESPACE_END
