// ltc/core/polygon_area_sampling.hpp -- uniform sampling of a planar polygon by area, the light
// sampling of most renderers ("light-area sampling"), and its density in solid angle as seen from
// a point: p_omega = |x - o|^2 / (A |cos theta_x|) (the change of measure dA -> d omega, e.g.
// Veach 1997 eq. 8.10). The baseline that the exact LTC sampler is measured against.
//
//   ltc::polygon_area_sampler<float> light(vertices, n);
//   glm::vec3 x = light.sample(u);                         // uniform on the polygon
//   float p = light.solid_angle_pdf(origin, x);            // density of normalize(x - origin)
//
// A convex polygon (a fan from vertex 0, triangles chosen by area; u.x is rescaled inside the
// chosen triangle, so one 2D sample serves and stratification is kept). n < 3, n > MaxVertices
// or zero area give an empty() sampler, whose samples are vertex 0 with density 0.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

namespace ltc {

/// Uniform sampling of a convex planar polygon by area (file comment).
template <typename T, std::size_t MaxVertices = 8>
class polygon_area_sampler {
  public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    LTC_HOST_DEVICE polygon_area_sampler() = default;

    LTC_HOST_DEVICE polygon_area_sampler(const vec3* vertices, std::size_t n) {
        if (n < 3 || n > MaxVertices) return;
        for (std::size_t i = 0; i < n; ++i) p_[i] = vertices[i];
        vec3 normal(T(0));
        T total(0);
        for (std::size_t i = 1; i + 1 < n; ++i) {
            const vec3 c = glm::cross(p_[i] - p_[0], p_[i + 1] - p_[0]);
            normal += c;
            total += glm::length(c) / T(2);
            cdf_[i - 1] = total;
        }
        const T l = glm::length(normal);
        if (!(total > T(0)) || !std::isfinite(total) || !(l > T(0))) return;
        n_ = n;
        area_ = total;
        normal_ = normal / l;
    }

    LTC_HOST_DEVICE bool empty() const { return !(area_ > T(0)); }
    LTC_HOST_DEVICE T area() const { return area_; }
    /// The unit normal (p1 - p0) x (p2 - p0) direction (Newell's sum over the fan).
    LTC_HOST_DEVICE const vec3& normal() const { return normal_; }

    /// A point uniformly distributed on the polygon, for u in [0, 1]^2.
    LTC_HOST_DEVICE vec3 sample(const vec2& u) const {
        if (empty()) return p_[0];
        const T target = glm::clamp(u.x, T(0), T(1)) * area_;
        std::size_t k = 0;
        while (k + 2 < n_ - 1 && cdf_[k] <= target) ++k;
        const T below = k > 0 ? cdf_[k - 1] : T(0);
        const T mass = cdf_[k] - below;
        const T u1 = mass > T(0) ? glm::clamp((target - below) / mass, T(0), T(1)) : T(0);
        // Uniform in the triangle (p0, p_k+1, p_k+2): the square-root warp (e.g. pbrt-v4's
        // SampleUniformTriangle in its older form).
        const T s = std::sqrt(u1);
        const T b0 = T(1) - s, b1 = s * (T(1) - glm::clamp(u.y, T(0), T(1)));
        return b0 * p_[0] + b1 * p_[k + 1] + (T(1) - b0 - b1) * p_[k + 2];
    }

    /// Density in solid angle, at `origin`, of the direction towards the sampled point x:
    /// |x - origin|^2 / (A |cos theta_x|); 0 when the direction grazes the polygon's plane.
    LTC_HOST_DEVICE T solid_angle_pdf(const vec3& origin, const vec3& x) const {
        if (empty()) return T(0);
        const vec3 d = x - origin;
        const T d2 = glm::dot(d, d);
        const T c = std::abs(glm::dot(d, normal_));  // |cos theta_x| |d|
        if (!(c > T(0))) return T(0);
        const T pdf = d2 * std::sqrt(d2) / (area_ * c);
        return std::isfinite(pdf) ? pdf : T(0);
    }

  private:
    vec3 p_[MaxVertices]{};
    T cdf_[MaxVertices]{};
    vec3 normal_{T(0), T(0), T(1)};
    T area_{0};
    std::size_t n_ = 0;
};

}  // namespace ltc
