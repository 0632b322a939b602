// The fuzz harness's checks of the polygon samplers (ltc/core/projected_solid_angle_sampling.hpp,
// ltc/core/ltc_polygon_sampling.hpp, ltc/core/polygon_area_sampling.hpp), called by
// tests/fuzz/fuzz_samplers.cpp for every input.
//
// Input: the harness's fuzzed matrix (M^-1 of the LTC, through the checked factory; skipped where
// it rejects it) and polygon (its first 8 vertices, and all of them, which gives an empty sampler
// beyond 8); then, consumed here, two points u of [0, 1]^2 (the ends included) and two offsets
// d1, d2 (fuzzed finite values) for a triangle (p0, p0 + d1, p0 + d2) around the first vertex
// (0, 0, 1) for an empty polygon): offsets of any size reach tiny and sliver triangles.
// Checks, in float and double, for any finite polygon (convex or not, planar or not):
//   - projected_solid_angle() and integral() finite and >= 0, area() finite and >= 0;
//   - sample(u).direction finite (unit where the sampler is not empty), sample(u).pdf finite and
//     >= 0, the evaluation count finite and at most the two solves' 2 x 40 iterations;
//   - pdf() of the sample and of the vertices' directions finite and >= 0; invert() of the same
//     in [0, 1]^2;
//   - the area sampler's point finite, its solid_angle_pdf finite and >= 0;
// and for triangles (always convex and planar) with a non-empty sampler: sample(u).pdf > 0.
#pragma once

#include "fuzz_common.hpp"

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/ltc_polygon_sampling.hpp>
#include <ltc/core/polygon_area_sampling.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>
#include <ltc/core/transformed.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace ltc_fuzz {

template <typename T>
void require_non_negative(T x, const char* what) {
    require_finite(x, what);
    if (!(x >= T(0))) {
        std::fprintf(stderr, "negative %s: %g\n", what, static_cast<double>(x));
        std::abort();
    }
}

template <typename T>
void require_unit_square(const glm::vec<2, T>& v, const char* what) {
    if (!(v.x >= T(0) && v.x <= T(1) && v.y >= T(0) && v.y <= T(1))) {
        std::fprintf(stderr, "%s outside [0, 1]^2: (%g, %g)\n", what, static_cast<double>(v.x),
                     static_cast<double>(v.y));
        std::abort();
    }
}

/// The checks shared by the projected and the LTC sampler (file comment).
template <typename T, typename Sampler>
void check_direction_sampler(const Sampler& s, const glm::vec<3, T>* v, std::size_t n, const glm::vec<2, T>& u,
                             bool convex, const char* what) {
    using vec3 = glm::vec<3, T>;
    int evaluations = 0;
    const ltc::polygon_sample<T> x = s.sample(u, evaluations);
    require_finite(x.direction, what);
    require_non_negative(x.pdf, what);
    if (evaluations < 0 || evaluations > 80) {
        std::fprintf(stderr, "%s: %d evaluations\n", what, evaluations);
        std::abort();
    }
    if (!s.empty()) {
        const T l = glm::length(x.direction);
        if (!(std::abs(l - T(1)) <= T(16) * std::numeric_limits<T>::epsilon())) {
            std::fprintf(stderr, "%s: direction of length %g\n", what, static_cast<double>(l));
            std::abort();
        }
        if (convex && !(x.pdf > T(0))) {
            std::fprintf(stderr, "%s: sample with pdf 0 from a non-empty triangle\n", what);
            std::abort();
        }
    }
    require_non_negative(s.pdf(x.direction), what);
    require_unit_square(s.invert(x.direction), what);
    for (std::size_t i = 0; i < n; ++i) {
        const vec3 w = ltc::detail::safe_normalize(v[i]);
        require_non_negative(s.pdf(w), what);
        require_unit_square(s.invert(w), what);
    }
}

template <typename T>
void check_sampling(FuzzedDataProvider& in, const glm::mat<3, 3, T>& m, const std::vector<glm::vec<3, T>>& v) {
    using vec2 = glm::vec<2, T>;
    std::vector<vec2> us;
    for (int i = 0; i < 2; ++i) {
        const T a = in.ConsumeProbability<T>(), b = in.ConsumeProbability<T>();
        us.push_back(vec2(a, b));
    }
    using vec3 = glm::vec<3, T>;
    const vec3 p0 = v.empty() ? vec3(T(0), T(0), T(1)) : v[0];
    const vec3 d1(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    const vec3 d2(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    const std::vector<vec3> triangle = {p0, p0 + d1, p0 + d2};
    const bool finite_triangle = std::isfinite(glm::dot(glm::abs(triangle[1]), vec3(1))) &&
                                 std::isfinite(glm::dot(glm::abs(triangle[2]), vec3(1)));
    const auto d = [&]() -> ltc::transformed<ltc::clamped_cosine<T>> {
        try {
            return ltc::transformed<ltc::clamped_cosine<T>>::checked_from_inverse(m);
        } catch (const ltc::invalid_transform&) {
            return ltc::transformed<ltc::clamped_cosine<T>>(glm::mat<3, 3, T>(T(1)));  // the clamped cosine
        }
    }();
    for (int which = 0; which < 3; ++which) {
        if (which == 2 && !finite_triangle) break;  // p0 + d overflowed
        const std::size_t n = which == 0 ? std::min<std::size_t>(v.size(), 8) : (which == 1 ? v.size() : 3);
        const vec3* pv = which == 2 ? triangle.data() : v.data();
        const bool triangle = n == 3;
        const ltc::projected_polygon_sampler<T> projected(pv, n);
        require_non_negative(projected.projected_solid_angle(), "projected solid angle");
        const ltc::ltc_polygon_sampler<T> restricted(d, pv, n);
        require_non_negative(restricted.integral(), "LTC polygon integral");
        const ltc::polygon_area_sampler<T> area(pv, n);
        require_non_negative(area.area(), "polygon area");
        for (const vec2& u : us) {
            check_direction_sampler<T>(projected, pv, n, u, triangle, "projected sampler");
            check_direction_sampler<T>(restricted, pv, n, u, triangle, "LTC polygon sampler");
            const glm::vec<3, T> x = area.sample(u);
            require_finite(x, "area sample");
            require_non_negative(area.solid_angle_pdf(glm::vec<3, T>(T(0)), x), "area sample's solid-angle pdf");
        }
    }
}

}  // namespace ltc_fuzz
