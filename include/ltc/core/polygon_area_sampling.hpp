// ltc/core/polygon_area_sampling.hpp -- uniform sampling of a planar polygon by area, the light
// sampling of most renderers ("light-area sampling"), and its density in solid angle as seen from
// a point: p_omega = |x - o|^2 / (A |cos theta_x|) (the change of measure dA -> d omega, e.g.
// Veach 1997 eq. 8.10). The baseline that the exact LTC sampler is compared with (docs/shadows.md).
//
//   ltc::polygon_area_sampler<float> light(vertices, n);
//   glm::vec3 x = light.sample(u);                         // uniform on the polygon
//   float p = light.solid_angle_pdf(origin, x);            // density of normalize(x - origin)
//
// A convex polygon (a fan from vertex 0, triangles chosen by area; u.x is rescaled inside the
// chosen triangle, so one 2D sample serves and stratification is kept). Any scale: coordinates are
// rescaled by exact powers of two. n < 3, n > max_vertices (MaxVertices, 8 by default; checked()
// throws ltc::invalid_polygon above it) or zero area give an empty() sampler, whose samples are
// vertex 0 (the origin for n = 0) with density 0.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/detail/polygon_check.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

LTC_NAMESPACE_BEGIN

/// Uniform sampling of a convex planar polygon by area (file comment).
template <typename T, std::size_t MaxVertices = 8>
class polygon_area_sampler {
  public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;
    /// The capacity: the most vertices a polygon may have, the MaxVertices template argument (a
    /// larger one holds larger polygons). n <= max_vertices is a precondition of the constructor,
    /// which gives an empty() sampler above it (it cannot throw: device code); checked() throws.
    static constexpr std::size_t max_vertices = MaxVertices;

    LTC_HOST_DEVICE polygon_area_sampler() = default;

    LTC_HOST_DEVICE polygon_area_sampler(const vec3* vertices, std::size_t n) {
        if (n >= 1) p_[0] = vertices[0];
        if (n < 3 || n > MaxVertices) return;
        for (std::size_t i = 0; i < n; ++i) p_[i] = vertices[i];
        // The fan's cross products of edges rescaled by an exact power of two 2^-e (e the
        // exponent of the largest coordinate difference): |c|^2 ~ |x|^4 neither over- nor
        // underflows at any scale; areas are kept in units of 2^2e.
        T largest(0);
        for (std::size_t i = 1; i < n; ++i) {
            const vec3 d = p_[i] - p_[0];
            largest = glm::max(largest, glm::max(std::abs(d.x), glm::max(std::abs(d.y), std::abs(d.z))));
        }
        if (!(largest > T(0)) || !std::isfinite(largest)) return;
        exponent_ = std::ilogb(largest);
        const auto edge = [&](std::size_t i) { return detail::rescale_by(p_[i] - p_[0], -exponent_); };
        vec3 normal(T(0));
        T total(0);
        for (std::size_t i = 1; i + 1 < n; ++i) {
            const vec3 c = glm::cross(edge(i), edge(i + 1));
            normal += c;
            total += glm::length(c) / T(2);
            cdf_[i - 1] = total;
        }
        const T l = glm::length(normal);
        if (!(total > T(0)) || !std::isfinite(total) || !(l > T(0))) return;
        n_ = n;
        scaled_area_ = total;
        normal_ = normal / l;
    }

    /// Like the constructor, but throws ltc::invalid_polygon (ltc/core/invalid_polygon.hpp) for
    /// n > max_vertices, n < 3 or a vertex not finite: input that is no polygon it can hold. (A
    /// polygon of zero area still gives an empty() sampler.)
    static polygon_area_sampler checked(const vec3* vertices, std::size_t n) {
        detail::require_polygon("ltc::polygon_area_sampler", vertices, n, max_vertices);
        return polygon_area_sampler(vertices, n);
    }

    LTC_HOST_DEVICE bool empty() const { return !(scaled_area_ > T(0)); }
    /// The area, saturated to the largest finite T where it exceeds T's range (and 0 where it
    /// underflows; the sampler itself works in rescaled units and does not use it).
    LTC_HOST_DEVICE T area() const {
        return glm::min(std::ldexp(scaled_area_, 2 * exponent_), detail::largest_finite<T>());
    }
    /// The unit normal (p1 - p0) x (p2 - p0) direction (Newell's sum over the fan).
    LTC_HOST_DEVICE const vec3& normal() const { return normal_; }

    /// A point uniformly distributed on the polygon, for u in [0, 1]^2.
    LTC_HOST_DEVICE vec3 sample(const vec2& u) const {
        if (empty()) return p_[0];
        const T target = glm::clamp(u.x, T(0), T(1)) * scaled_area_;
        std::size_t k = 0;
        while (k + 2 < n_ - 1 && cdf_[k] <= target) ++k;
        const T below = k > 0 ? cdf_[k - 1] : T(0);
        const T mass = cdf_[k] - below;
        const T u1 = mass > T(0) ? glm::clamp((target - below) / mass, T(0), T(1)) : T(0);
        // Uniform in the triangle (p0, p_k+1, p_k+2): the square-root warp (e.g. pbrt-v4's
        // SampleUniformTriangle in its older form).
        const T s = std::sqrt(u1);
        const T b0 = T(1) - s, b1 = s * (T(1) - glm::clamp(u.y, T(0), T(1)));
        const vec3 &a = p_[0], &b = p_[k + 1], &c = p_[k + 2];
        // The triangle's bounding box holds the point: clamping to it keeps the rounding of the
        // weighted sum from stepping past the largest finite T for vertices near it.
        return glm::clamp(b0 * a + b1 * b + (T(1) - b0 - b1) * c, glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)));
    }

    /// Density in solid angle, at `origin`, of the direction towards the sampled point x:
    /// |x - origin|^2 / (A |cos theta_x|), computed in rescaled units (no overflow of |x - o|^3);
    /// 0 when the direction grazes the polygon's plane or the density leaves T's range.
    LTC_HOST_DEVICE T solid_angle_pdf(const vec3& origin, const vec3& x) const {
        if (empty()) return T(0);
        const vec3 d = x - origin;
        const T m = glm::max(std::abs(d.x), glm::max(std::abs(d.y), std::abs(d.z)));
        if (!(m > T(0)) || !std::isfinite(m)) return T(0);
        const int e = std::ilogb(m);
        const vec3 ds = detail::rescale_by(d, -e);
        const T d2 = glm::dot(ds, ds);
        const T c = std::abs(glm::dot(ds, normal_));  // |cos theta_x| |ds|
        if (!(c > T(0))) return T(0);
        const T pdf = std::ldexp(d2 * std::sqrt(d2) / (scaled_area_ * c), 2 * (e - exponent_));
        return std::isfinite(pdf) ? pdf : T(0);
    }

  private:
    vec3 p_[MaxVertices]{};
    T cdf_[MaxVertices]{};
    vec3 normal_{T(0), T(0), T(1)};
    T scaled_area_{0};  // the area in units of 2^(2 exponent_)
    int exponent_ = 0;
    std::size_t n_ = 0;
};

LTC_NAMESPACE_END
