// ltc/core/ltc_polygon_sampling.hpp -- sampling a Linearly Transformed Cosine restricted to a
// polygon: directions w in P with density D(w) / I_D, I_D = int_P D (eq. 3). Exact, through the
// projected solid angle sampler (ltc/core/projected_solid_angle_sampling.hpp) in the cosine's
// space (eq. 1 and its Jacobian, paper appendix A): the stochastic part of the ratio estimator
// (ltc/shading/shadowed_polygon_light.hpp).
//
//   ltc::ltc_polygon_sampler<float> s(d, vertices, n);   // d: transformed<clamped_cosine<float>>
//   ltc::polygon_sample<float> x = s.sample(u);           // x.pdf = d.eval(x.direction) / s.integral()
//
// Conventions: vertices in D's frame; a convex planar polygon of at most max_vertices
// (MaxVertices, 8 by default) vertices: a precondition of the constructor, which checked()
// enforces by throwing ltc::invalid_polygon. Degenerate cases: those of the projected sampler,
// which give an empty() sampler.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/core/detail/polygon_check.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN

/// D restricted to a convex polygon, for D = transformed<clamped_cosine<T, Policy>>: the
/// projected solid angle sampler in the cosine's space,
///   w_o ~ max(0, w_o.z) / E over M^-1 P (clipped),   E = pi I_D;
///   w = M w_o / |M w_o|,   density (w_o.z / E) |M^-1| / |M^-1 w|^3 = D(w) pi / E = D(w) / I_D
/// (eq. 1 and its Jacobian, paper appendix A). With the polygon's integral known in closed form,
/// an estimate sum f / p over these samples of any f close to D has variance close to zero.
///
/// The polygon: convex and planar, at most max_vertices vertices: a precondition of the
/// constructor (device code: it cannot throw), which checked() enforces by throwing
/// ltc::invalid_polygon (ltc/core/invalid_polygon.hpp). See the projected sampler for the
/// degenerate cases, which give an empty() sampler. M^-1 P is computed in T, and once more
/// in the projected sampler's wider type where that sampler widens its fan (a tiny or grazing
/// M^-1 P in float): then I_D carries no rounding of M^-1 p_i in T.
template <typename T, std::size_t MaxVertices = 8>
class ltc_polygon_sampler {
  public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;
    using mat3 = glm::mat<3, 3, T>;
    /// The capacity: the most vertices a polygon may have, the MaxVertices template argument (a
    /// larger one holds larger polygons). n <= max_vertices is a precondition of the constructor,
    /// which gives an empty() sampler above it (it cannot throw: device code); checked() throws.
    static constexpr std::size_t max_vertices = MaxVertices;

    LTC_HOST_DEVICE ltc_polygon_sampler() = default;

    /// vertices[0..n) in D's frame (the shading frame for the GGX table's lobes). n > max_vertices
    /// (a precondition) gives an empty() sampler whose integral() is 0, not D's integral.
    template <typename Policy>
    LTC_HOST_DEVICE ltc_polygon_sampler(const transformed<clamped_cosine<T, Policy>>& d, const vec3* vertices,
                                        std::size_t n)
        : lobe_(d), m_(d.matrix()) {
        if (n > MaxVertices) return;
        vec3 local[MaxVertices];
        const detail::transformed_vertices<T> to_cosine{lobe_.inverse_matrix(), vertices};
        for (std::size_t i = 0; i < n; ++i) local[i] = to_cosine(i);
        cosine_ = projected_polygon_sampler<T, MaxVertices>(local, n, lobe_.inverse_matrix(), vertices);
        // A numerically degenerate M can map even the polygon's interior outside it and back:
        // then no sample could have pdf > 0, and the polygon counts as empty.
        if (!cosine_.empty()) {
            inside_ = detail::safe_normalize(m_ * cosine_.interior());
            usable_ = density(inside_) > T(0);
        }
    }

    /// Like the constructor, but throws ltc::invalid_polygon (ltc/core/invalid_polygon.hpp) for
    /// n > max_vertices, n < 3 or a vertex not finite: input that is no polygon it can hold. (A
    /// polygon below D's horizon, or seen edge-on, still gives an empty() sampler.)
    template <typename Policy>
    static ltc_polygon_sampler checked(const transformed<clamped_cosine<T, Policy>>& d, const vec3* vertices,
                                       std::size_t n) {
        detail::require_polygon("ltc::ltc_polygon_sampler", vertices, n, max_vertices);
        return ltc_polygon_sampler(d, vertices, n);
    }

    /// No direction to sample: the polygon holds none of D's support, M is too degenerate to
    /// sample through (integral() may be > 0 then), or a precondition is broken (integral() 0);
    /// sample() has pdf 0 and pdf() is 0. Every sample of a sampler that is not empty() has
    /// pdf() > 0, the pdf it carries.
    LTC_HOST_DEVICE bool empty() const { return !usable_; }

    /// I_D: the integral of D over the polygon (the clamped cosine's over M^-1 P, clipped; also
    /// for an empty() sampler whose M is too degenerate to sample through).
    LTC_HOST_DEVICE T integral() const { return cosine_.projected_solid_angle() / pi<T>(); }

    /// A direction with density D(w) / I_D in the polygon, and that density.
    LTC_HOST_DEVICE polygon_sample<T> sample(const vec2& u) const {
        int evaluations = 0;
        return sample(u, evaluations);
    }

    /// The returned pdf is pdf(direction): the round trip M w_o, M^-1 w can carry a sample next to
    /// the edge of M^-1 P (or its horizon) just outside, where pdf() is 0; such a sample is moved
    /// towards the polygon's interior by the smallest power-of-16 multiple of epsilon that brings
    /// it back (as transformed<>::sample does; a bias confined to a set of measure ~cond(M)
    /// epsilon).
    LTC_HOST_DEVICE polygon_sample<T> sample(const vec2& u, int& evaluations) const {
        if (empty()) return polygon_sample<T>{};  // pdf 0
        polygon_sample<T> x = cosine_.sample(u, evaluations);
        vec3 wo = x.direction;
        x.direction = detail::safe_normalize(m_ * wo);
        x.pdf = pdf(x.direction);
        if (!(x.pdf > T(0))) {
            const vec3 inside = cosine_.interior();
            T lift = detail::epsilon<T>();
            for (int i = 0; i < 16 && !(x.pdf > T(0)); ++i, lift *= T(16)) {
                wo = detail::safe_normalize(wo + lift * inside);
                x.direction = detail::safe_normalize(m_ * wo);
                x.pdf = pdf(x.direction);
            }
            // Where no lift helps (M near singular): the image of the interior, checked usable.
            if (!(x.pdf > T(0))) x.direction = inside_, x.pdf = pdf(inside_);
        }
        return x;
    }

    /// Density of sample() at the unit direction w: D(w) / I_D inside the polygon, else 0.
    LTC_HOST_DEVICE T pdf(const vec3& w) const { return usable_ ? density(w) : T(0); }

    /// u with sample(u).direction == w (up to rounding), for w in the polygon.
    LTC_HOST_DEVICE vec2 invert(const vec3& w) const {
        return cosine_.invert(detail::safe_normalize(lobe_.inverse_matrix() * w));
    }

  private:
    LTC_HOST_DEVICE T density(const vec3& w) const {
        // A Jacobian past T's range (M near singular, w near its null direction): saturated, and
        // never multiplied into a zero density (0 x Inf).
        const T p = cosine_.pdf(detail::safe_normalize(lobe_.inverse_matrix() * w));
        return p > T(0) ? glm::min(p * lobe_.jacobian(w), detail::largest_finite<T>()) : T(0);
    }

    transformed<clamped_cosine<T>> lobe_{mat3(T(1))};  // D's M^-1 and |M^-1|: the Jacobian of eq. 1
    mat3 m_{T(1)};
    vec3 inside_{T(0), T(0), T(1)};  // M (the clipped M^-1 P's interior direction)
    bool usable_ = false;
    projected_polygon_sampler<T, MaxVertices> cosine_;
};

LTC_NAMESPACE_END
