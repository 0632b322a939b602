// ltc/reference/ground_truth.hpp -- Monte Carlo ground truth for polygonal lights: the integral of a BRDF
// model's rho(V, L) cos(theta_L) over a spherical polygon, with its standard error.
//
//   #include <ltc/reference/ground_truth.hpp>
//   #include <ltc/fitting/brdf/ggx.hpp>
//   ltc::ground_truth::options opt;                      // samples, seed, heuristic, ...
//   ltc::ground_truth::estimate e = ltc::ground_truth::integrate(
//       ltc::brdf::ggx<double>{}, V, alpha, vertices, n, opt);
//   // e.mean +- e.standard_error, after e.samples iterations
//
// This is the reference that the LTC shading is measured against (paper section 4's target,
// integrated over a polygon instead of fitted). It works in double, in the local shading frame
// of ltc/fitting/brdf/model.hpp (N = +z, V.z > 0), and is not meant for a renderer's hot path (it
// allocates one small vector per polygon).
//
// Estimator. Each iteration draws one direction from each of two techniques and combines them
// with multiple importance sampling (Veach and Guibas 1995; one sample per technique, so
// the balance heuristic weight of technique k is p_k / (p_brdf + p_polygon)):
//   - BRDF sampling: L ~ model.sample(V, u, alpha), density model.pdf(V, L, alpha);
//   - polygon sampling: L uniform in solid angle over the spherical polygon (below).
// The integrand is model.eval(V, L, alpha) times the polygon's indicator, so the estimate is
// the integral over the *set* of directions that the polygon covers, whatever its winding:
// the two-sided integral. A one-sided light is 0 from behind; multiply by the facing yourself.
// The iterations are independent, so the standard error is the sample standard deviation of
// the per-iteration values over sqrt(iterations) (Welford's update, in double).
//
// Polygon sampling. The polygon is triangulated as a fan from vertex 0; each fan triangle is
// the projection of a planar triangle that does not contain the origin, so it lies in an open
// hemisphere. A triangle is chosen with probability proportional to its solid angle (Van
// Oosterom and Strackee 1983) and sampled uniformly by Arvo's method (Arvo 1995, "Stratified
// sampling of spherical triangles", SIGGRAPH; in the arrangement of pbrt-v4's
// SampleSphericalTriangle). Non-convex polygons are handled exactly: fan triangles whose
// orientation opposes the polygon's (they cancel parts of other triangles) are never sampled,
// the density at w is (number of same-orientation fan triangles containing w) / (their total
// solid angle), and a sample that lands where the winding number is 0 contributes 0. For a
// convex polygon this is exactly uniform: density 1 / Omega inside.
//
// Determinism: a fixed seed gives the same random numbers on every platform (SplitMix64,
// doubles from the top 53 bits, no <random> distribution, drawn in a sequenced order), hence
// the same estimate up to the last-bit differences of the platform's libm.
//
// Caveat: the standard error is estimated from the iterations, so it cannot see events that
// have not happened. For a light much smaller than the BRDF lobe, BRDF samples hit it so rarely
// (and then carry a tiny weight) that a run may see none; the estimate is then low by that
// technique's share, about Omega * p_brdf / (1 + Omega * p_brdf) of the integral (1.5e-5 for the
// 5e-5 sr triangle of the tests), which the standard error does not include.
#pragma once

#include <ltc/detail/math.hpp>
#include <ltc/core/polygon.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ltc {
namespace ground_truth {

/// SplitMix64 (Steele, Lea and Flood 2014): a small, fast, statistically sound generator whose
/// sequence is fixed by its seed.
class splitmix64 {
  public:
    explicit splitmix64(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1).
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Uniform in [0, 1)^2 and [0, 1)^3, drawn in component order (the order in which the
    /// arguments of a constructor are evaluated is unspecified, so never write
    /// dvec2(uniform(), uniform()): GCC and Clang would draw different points).
    glm::dvec2 uniform2() {
        const double x = uniform();
        const double y = uniform();
        return {x, y};
    }
    glm::dvec3 uniform3() {
        const double x = uniform();
        const double y = uniform();
        const double z = uniform();
        return {x, y, z};
    }

  private:
    std::uint64_t state_;
};

/// Uniform sampling of the spherical triangle (a, b, c) of unit vectors by Arvo's method (Arvo
/// 1995; pbrt-v4's arrangement), with everything that does not depend on the sample computed
/// once. Either orientation; the density is 1 / (solid angle).
class spherical_triangle_sampler {
  public:
    spherical_triangle_sampler(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) : a_(a), b_(b) {
        using glm::dvec3;
        dvec3 n_ab = glm::cross(a, b), n_bc = glm::cross(b, c), n_ca = glm::cross(c, a);
        const double lab = glm::length(n_ab), lbc = glm::length(n_bc), lca = glm::length(n_ca);
        if (!(lab > 0.0) || !(lbc > 0.0) || !(lca > 0.0)) return;  // coincident vertices
        n_ab /= lab;
        n_bc /= lbc;
        n_ca /= lca;
        // Angle between unit vectors by 2 asin(|x -+ y| / 2) (accurate at every angle).
        const auto angle = [](const dvec3& x, const dvec3& y) {
            return glm::dot(x, y) < 0.0 ? pi<double>() - 2.0 * std::asin(glm::min(1.0, glm::length(x + y) / 2.0))
                                        : 2.0 * std::asin(glm::min(1.0, glm::length(x - y) / 2.0));
        };
        const double alpha = angle(n_ab, -n_ca);  // interior angles at a, b, c
        const double beta = angle(n_bc, -n_ab);
        const double gamma = angle(n_ca, -n_bc);
        area_ = alpha + beta + gamma - pi<double>();
        cos_alpha_ = std::cos(alpha);
        sin_alpha_ = std::sin(alpha);
        cos_c_ = glm::dot(a, b);
        c_perp_ = detail::safe_normalize(c - glm::dot(c, a) * a);
        valid_ = true;
    }

    /// Solid angle from the interior angles (Girard's theorem).
    double solid_angle() const { return valid_ ? area_ : 0.0; }

    /// u.x sets the solid angle of the sub-triangle (a, b, c') with c' on the arc from a to c,
    /// u.y the position on the arc from b to c'. Degenerate triangles return a.
    glm::dvec3 sample(const glm::dvec2& u) const {
        if (!valid_) return a_;
        const double sub_pi = pi<double>() + u.x * area_;  // sampled area + pi
        const double s = std::sin(sub_pi), c = std::cos(sub_pi);
        const double sin_phi = s * cos_alpha_ - c * sin_alpha_;
        const double cos_phi = c * cos_alpha_ + s * sin_alpha_;
        const double k1 = cos_phi + cos_alpha_;
        const double k2 = sin_phi - sin_alpha_ * cos_c_;
        const double den = (k2 * sin_phi + k1 * cos_phi) * sin_alpha_;
        double cos_bp = den != 0.0 ? (k2 + (k2 * cos_phi - k1 * sin_phi) * cos_alpha_) / den : 1.0;
        cos_bp = glm::clamp(cos_bp, -1.0, 1.0);
        const double sin_bp = std::sqrt(glm::max(0.0, 1.0 - cos_bp * cos_bp));
        const glm::dvec3 cp = cos_bp * a_ + sin_bp * c_perp_;  // c' on the arc from a towards c
        // Uniform in the sub-triangle's new area: cos(theta) along the arc from b to c'.
        const double cos_theta = 1.0 - u.y * (1.0 - glm::dot(cp, b_));
        const double sin_theta = std::sqrt(glm::max(0.0, 1.0 - cos_theta * cos_theta));
        const glm::dvec3 cp_perp = detail::safe_normalize(cp - glm::dot(cp, b_) * b_);
        return detail::safe_normalize(cos_theta * b_ + sin_theta * cp_perp);
    }

  private:
    glm::dvec3 a_, b_, c_perp_{0.0};
    double area_ = 0.0, cos_alpha_ = 1.0, sin_alpha_ = 0.0, cos_c_ = 1.0;
    bool valid_ = false;
};

/// A uniformly distributed direction in the spherical triangle (a, b, c) of unit vectors, for
/// u in [0, 1)^2 (spherical_triangle_sampler, for a single sample).
inline glm::dvec3 sample_spherical_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                            const glm::dvec2& u) {
    return spherical_triangle_sampler(a, b, c).sample(u);
}

/// A spherical polygon seen from the origin, triangulated as a fan from vertex 0: uniform
/// sampling, its density and the winding number (file comment).
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

/// How the two techniques are weighted: balance (p_k / sum p) or power (p_k^2 / sum p^2).
enum class heuristic { balance, power };

/// Which techniques run (both = MIS; the single ones are for tests and comparisons).
enum class techniques { mis, brdf_only, polygon_only };

struct options {
    std::uint64_t samples = 1u << 16;  ///< iterations (one draw per technique each), or a batch
    std::uint64_t seed = 1;
    heuristic weighting = heuristic::balance;
    techniques use = techniques::mis;
    /// Adaptive mode when either target is > 0: batches of `samples` iterations until
    /// standard_error <= max(target_relative_error * |mean|, target_absolute_error), or
    /// max_samples iterations.
    double target_relative_error = 0.0;
    double target_absolute_error = 0.0;
    std::uint64_t max_samples = 1u << 24;
};

/// mean +- standard_error: an unbiased estimate of the integral and its standard error.
struct estimate {
    double mean = 0.0;
    double standard_error = 0.0;
    std::uint64_t samples = 0;
};

/// Monte Carlo estimate of int_P model.eval(V, L, alpha) dL over the spherical polygon
/// vertices[0..n) (local frame, N = +z). Model: any type with eval/pdf/sample as in
/// ltc/fitting/brdf/model.hpp for T = double, called through an instance so that stateful models work.
template <typename Model>
estimate integrate(const Model& model, const glm::dvec3& V, double alpha, const glm::dvec3* vertices,
                   std::size_t n, const options& opt = {}) {
    const spherical_polygon poly(vertices, n);
    estimate e;
    if (poly.empty()) return e;  // no solid angle: the integral is 0
    splitmix64 rng(opt.seed);
    const bool use_brdf = opt.use != techniques::polygon_only;
    const bool use_poly = opt.use != techniques::brdf_only;
    const auto weight = [&](double p, double q) {  // MIS weight of the technique with density p
        if (opt.use != techniques::mis) return 1.0;
        if (opt.weighting == heuristic::power) {
            const double m = glm::max(p, q);  // scale to avoid overflow of the squares
            const double a = p / m, b = q / m;
            return a * a / (a * a + b * b);
        }
        return p / (p + q);
    };
    double mean = 0.0, m2 = 0.0;
    std::uint64_t count = 0;
    const std::uint64_t batch = opt.samples > 0 ? opt.samples : 1;
    for (;;) {
        for (std::uint64_t it = 0; it < batch; ++it) {
            double x = 0.0;
            if (use_brdf) {
                const glm::dvec2 u = rng.uniform2();
                const glm::dvec3 L = model.sample(V, u, alpha);
                const double p_b = model.pdf(V, L, alpha);
                bool in = false;
                double p_p = 0.0;
                if (p_b > 0.0) poly.classify(L, in, p_p);
                if (in) {
                    const double f = model.eval(V, L, alpha);
                    if (f > 0.0) x += weight(p_b, use_poly ? p_p : 0.0) * f / p_b;
                }
            }
            if (use_poly) {
                const glm::dvec3 u = rng.uniform3();
                const glm::dvec3 L = poly.sample(u);
                bool in = false;
                double p_p = 0.0;
                poly.classify(L, in, p_p);
                if (p_p > 0.0 && in) {
                    const double f = model.eval(V, L, alpha);
                    if (f > 0.0) x += weight(p_p, use_brdf ? model.pdf(V, L, alpha) : 0.0) * f / p_p;
                }
            }
            ++count;
            const double d = x - mean;
            mean += d / static_cast<double>(count);
            m2 += d * (x - mean);
        }
        const double var = count > 1 ? m2 / static_cast<double>(count - 1) : 0.0;
        e.mean = mean;
        e.standard_error = std::sqrt(var / static_cast<double>(count));
        e.samples = count;
        const bool adaptive = opt.target_relative_error > 0.0 || opt.target_absolute_error > 0.0;
        if (!adaptive || count >= opt.max_samples ||
            e.standard_error <= glm::max(opt.target_relative_error * std::abs(e.mean), opt.target_absolute_error))
            break;
    }
    return e;
}

}  // namespace ground_truth
}  // namespace ltc
