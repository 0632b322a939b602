// ltc/reference/textured_ground_truth.hpp -- Monte Carlo ground truth for textured quad lights: the RGB
// integral of L(w) f(w) over a quad, where L is the (unfiltered) texture seen through the quad
// and f a lobe: rho(V, w) cos(theta_w) of a BRDF model (ltc::brdf::ggx), or an LTC's D(w).
//
//   ltc::textured_ground_truth::options opt;                          // samples, seed
//   auto radiance = [&](double u, double v) { return ltc::bilinear_image_lookup(w, h, img, u, v); };
//   auto e = ltc::textured_ground_truth::integrate(
//       ltc::textured_ground_truth::brdf_lobe<ltc::brdf::ggx<double>>{V, alpha}, quad, radiance, opt);
//   // e.mean +- e.standard_error (per channel)
//
// Frame: the local shading frame of ltc/brdf/model.hpp (shading point at the origin, N = +z).
// The quad quad[0..3] carries uv (0,0), (1,0), (1,1), (0,1) on the parallelogram q_0 + u (q_1 -
// q_0) + v (q_3 - q_0), the mapping of ltc/shading/lights/textured_quad_light.hpp. The integral is
// over the set of directions that hit the quad, whatever its orientation (two-sided). Degenerate
// cases: a zero-area quad gives 0. Deterministic for a fixed seed (the estimator: integrate).
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

LTC_NAMESPACE_BEGIN
namespace textured_ground_truth {

struct options {
    std::size_t samples = std::size_t(1) << 16;  ///< iterations (each: one sample per technique)
    std::uint64_t seed = 1;
};

struct estimate {
    glm::dvec3 mean{0.0};
    glm::dvec3 standard_error{0.0};
    std::size_t samples = 0;
};

/// rho(V, w) cos theta_w of a BRDF model (ltc/brdf/model.hpp) for the view V and alpha.
template <typename Model>
struct brdf_lobe {
    glm::dvec3 V{0.0, 0.0, 1.0};
    double alpha = 0.5;
    double eval(const glm::dvec3& w) const { return Model::eval(V, w, alpha); }
    double pdf(const glm::dvec3& w) const { return Model::pdf(V, w, alpha); }
    glm::dvec3 sample(const glm::dvec2& u) const { return Model::sample(V, u, alpha); }
};

/// The LTC distribution D(w) itself (normalized; sampled by Algorithm 1, pdf = D).
struct ltc_lobe {
    transformed<clamped_cosine<double>> d{glm::dmat3(1.0)};
    double eval(const glm::dvec3& w) const { return d.eval(w); }
    double pdf(const glm::dvec3& w) const { return d.pdf(w); }
    glm::dvec3 sample(const glm::dvec2& u) const { return d.sample(u); }
};

/// Piecewise-constant density on [0, 1]^2 proportional to non-negative texel weights of a
/// width x height grid (row-major, texel (x, y) covering [x/w, (x+1)/w] x [y/h, (y+1)/h]), mixed
/// half and half with the uniform density (so p_uv >= 1/2 everywhere: never worse than half
/// the plain uniform sampling). All-zero weights give the uniform density.
class texel_distribution {
  public:
    texel_distribution(int width, int height, const double* weights) : w_(width), h_(height) {
        cdf_.resize(std::size_t(width) * height + 1, 0.0);
        for (std::size_t i = 0; i < std::size_t(width) * height; ++i)
            cdf_[i + 1] = cdf_[i] + (weights[i] > 0 && std::isfinite(weights[i]) ? weights[i] : 0.0);
        total_ = cdf_.back();
    }
    /// Density at uv (per unit uv area).
    double pdf(double u, double v) const {
        if (!(total_ > 0)) return 1.0;
        const int x = std::min(std::max(int(u * w_), 0), w_ - 1), y = std::min(std::max(int(v * h_), 0), h_ - 1);
        const std::size_t i = std::size_t(y) * w_ + x;
        return 0.5 + 0.5 * (cdf_[i + 1] - cdf_[i]) / total_ * double(w_) * double(h_);
    }
    /// uv from three uniform numbers (the first picks the mixture component).
    glm::dvec2 sample(double s, double a, double b) const {
        if (!(total_ > 0) || s < 0.5) return glm::dvec2(a, b);
        const double target = a * total_;
        std::size_t i = std::size_t(std::upper_bound(cdf_.begin() + 1, cdf_.end(), target) - (cdf_.begin() + 1));
        i = std::min(i, cdf_.size() - 2);
        const int x = int(i % std::size_t(w_)), y = int(i / std::size_t(w_));
        const double a2 = (cdf_[i + 1] > cdf_[i]) ? (target - cdf_[i]) / (cdf_[i + 1] - cdf_[i]) : 0.5;
        return glm::dvec2((x + std::min(std::max(a2, 0.0), 1.0)) / w_, (y + b) / h_);
    }

  private:
    int w_, h_;
    std::vector<double> cdf_;
    double total_ = 0;
};

namespace detail {

class splitmix {
  public:
    explicit splitmix(std::uint64_t seed) : s_(seed) {}
    double uniform() {
        std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return static_cast<double>(z >> 11) * 0x1.0p-53;
    }

  private:
    std::uint64_t s_;
};

struct parallelogram {
    glm::dvec3 q0, e1, e3, n;  // n = e1 x e3
    double area = 0, det = 0;  // area = |n|, det = |n|^2
    /// Hit of the ray t w (t > 0) with the parallelogram: false if missed; else uv and t.
    bool hit(const glm::dvec3& w, glm::dvec2& uv, double& t) const {
        const double denom = glm::dot(n, w);
        if (!(denom != 0)) return false;
        t = glm::dot(n, q0) / denom;
        if (!(t > 0) || !std::isfinite(t)) return false;
        const glm::dvec3 r = t * w - q0;
        uv.x = glm::dot(glm::cross(r, e3), n) / det;
        uv.y = glm::dot(glm::cross(e1, r), n) / det;
        return uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1;
    }
    /// Solid-angle density of area sampling in the direction w whose hit is at distance t.
    double pdf(const glm::dvec3& w, double t) const {
        const double c = std::abs(glm::dot(n, w)) / area;
        return c > 0 ? t * t / (area * c) : 0.0;
    }
};

}  // namespace detail

/// The integral of L(uv(w)) lobe(w) over the quad. radiance(u, v) -> glm::dvec3 (convertible).
/// A degenerate quad (zero area) gives 0.
///
/// Estimator: per iteration, one direction from each of two techniques, combined by multiple
/// importance sampling with the balance heuristic (Veach and Guibas 1995):
///   - lobe sampling: w ~ lobe.sample(u), density lobe.pdf(w) per steradian;
///   - area sampling: a point x = q_0 + u e_1 + v e_3 with (u, v) of density p_uv (uniform on
///     [0, 1]^2 by default; optionally the defensive mixture 1/2 uniform + 1/2 piecewise constant
///     proportional to given texel weights, e.g. the texels' luminance: see texel_distribution,
///     which puts samples on a small bright detail), w = x / |x|, density per steradian
///     p_A(w) = p_uv(u, v) |x|^2 / (A |cos theta_x|) (theta_x between w and the quad's normal).
/// Each sample contributes f(w) L(uv(w)) / (p_lobe(w) + p_A(w)) (balance heuristic, one sample
/// per technique), so the iteration's value is unbiased; iterations are independent and the
/// standard error is the per-channel sample standard deviation over sqrt(iterations).
/// Deterministic for a fixed seed (SplitMix64, doubles from the top 53 bits).
template <typename Lobe, typename Radiance>
inline estimate integrate(const Lobe& lobe, const glm::dvec3 quad[4], const Radiance& radiance,
                          const options& opt = options(), const texel_distribution* area_density = nullptr) {
    estimate e;
    detail::parallelogram pg;
    pg.q0 = quad[0];
    pg.e1 = quad[1] - quad[0];
    pg.e3 = quad[3] - quad[0];
    pg.n = glm::cross(pg.e1, pg.e3);
    pg.det = glm::dot(pg.n, pg.n);
    pg.area = std::sqrt(pg.det);
    if (!(pg.area > 0) || opt.samples == 0) return e;
    detail::splitmix rng(opt.seed);
    glm::dvec3 mean(0.0), m2(0.0);
    for (std::size_t i = 0; i < opt.samples; ++i) {
        glm::dvec3 value(0.0);
        // Lobe sampling.
        {
            const double u1 = rng.uniform();
            const double u2 = rng.uniform();
            const glm::dvec3 w = lobe.sample(glm::dvec2(u1, u2));
            glm::dvec2 uv;
            double t;
            if (pg.hit(w, uv, t)) {
                const double f = lobe.eval(w);
                const double puv = area_density ? area_density->pdf(uv.x, uv.y) : 1.0;
                const double p = lobe.pdf(w) + puv * pg.pdf(w, t);
                if (f > 0 && p > 0) value += (f / p) * glm::dvec3(radiance(uv.x, uv.y));
            }
        }
        // Area sampling.
        {
            const double s = rng.uniform();
            const double a = rng.uniform();
            const double b = rng.uniform();
            const glm::dvec2 uv = area_density ? area_density->sample(s, a, b) : glm::dvec2(a, b);
            const double u = uv.x, v = uv.y;
            const double puv = area_density ? area_density->pdf(u, v) : 1.0;
            const glm::dvec3 x = pg.q0 + u * pg.e1 + v * pg.e3;
            const double t = glm::length(x);
            if (t > 0) {
                const glm::dvec3 w = x / t;
                const double f = lobe.eval(w);
                const double p = lobe.pdf(w) + puv * pg.pdf(w, t);
                if (f > 0 && p > 0) value += (f / p) * glm::dvec3(radiance(u, v));
            }
        }
        // Welford.
        const double k = double(i + 1);
        const glm::dvec3 delta = value - mean;
        mean += delta / k;
        m2 += delta * (value - mean);
    }
    e.samples = opt.samples;
    e.mean = mean;
    if (opt.samples > 1) e.standard_error = glm::sqrt(m2 / (double(opt.samples - 1) * double(opt.samples)));
    return e;
}

}  // namespace textured_ground_truth
LTC_NAMESPACE_END
