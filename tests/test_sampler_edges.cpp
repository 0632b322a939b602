// The samplers at their edges (ltc/core/spherical_triangle_sampling.hpp,
// spherical_polygon_sampling.hpp, projected_solid_angle_sampling.hpp, ltc_polygon_sampling.hpp):
//   (a) every sample of the solid-angle samplers has pdf > 0 (a renderer divides by it): the
//       reported triangle and u, and a 2000 x 2000 grid of u plus the borders of the square, on
//       that triangle, a 1e-5 rad quad and larger shapes; directions a few margins outside an edge
//       still have pdf 0.
// Every input is exact in float (the references see the same numbers).
#include <ltc/core/spherical_polygon_sampling.hpp>
#include <ltc/core/spherical_triangle_sampling.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using glm::dvec3;

/// A polygon given in float (so that float and double samplers see the same vertices).
struct shape {
    std::string name;
    std::vector<glm::vec3> v;
};

/// The triangle of the report, the 1e-5 rad quad of the report, and larger ones.
std::vector<shape> edge_shapes() {
    return {
        {"reported triangle", {{0.3f, 0.2f, 0.9f}, {0.3008f, 0.2001f, 0.9f}, {0.3002f, 0.2009f, 0.9003f}}},
        {"1e-5 rad quad",
         {{0.3999899923801422f, -0.30000799894332886f, 0.7999979853630066f},
          {0.40000998973846436f, -0.30000799894332886f, 0.8000019788742065f},
          {0.40000998973846436f, -0.29999199509620667f, 0.8000019788742065f},
          {0.3999899923801422f, -0.29999199509620667f, 0.7999979853630066f}}},
        {"triangle", {{0, 0, 1}, {1, 0, 0.25f}, {0, 1, 0.5f}}},
        {"pentagon", {{1, 0, 1.25f}, {0.25f, 1, 1.0625f}, {-0.75f, 0.5f, 0.8125f}, {-0.75f, -0.5f, 0.8125f},
                      {0.25f, -1, 1.0625f}}},
    };
}

template <typename T>
std::vector<glm::vec<3, T>> as(const std::vector<glm::vec3>& v) {
    return {v.begin(), v.end()};
}

/// The u of the sweep: the centres of an n x n grid, and n points on each border of the square
/// (0 and the largest T below 1).
template <typename T>
std::vector<glm::vec<2, T>> sweep(int n) {
    const T one = T(1) - std::numeric_limits<T>::epsilon() / 2;
    std::vector<glm::vec<2, T>> u;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) u.emplace_back(T((i + 0.5) / n), T((j + 0.5) / n));
    for (int i = 0; i < n; ++i) {
        const T t = T(double(i) / n);
        u.insert(u.end(), {{T(0), t}, {one, t}, {t, T(0)}, {t, one}});
    }
    return u;
}

/// Counts the u whose sample has pdf 0, or pdf at the sample's antipode > 0.
template <typename T, typename Sampler>
void check_pdf_of_samples(const Sampler& s, const std::vector<glm::vec<2, T>>& us, const std::string& name) {
    long zero = 0, antipode = 0;
    for (const auto& u : us) {
        const glm::vec<3, T> w = s.sample(u);
        zero += !(s.pdf(w) > T(0));
        antipode += s.pdf(-w) != T(0);
    }
    INFO(name << ": " << us.size() << " samples, " << zero << " with pdf 0, " << antipode << " antipodes with pdf > 0");
    CHECK(zero == 0);
    CHECK(antipode == 0);
}

/// Directions 3 margins outside the middle of each edge (in double, then rounded to T: the
/// rounding, a few u, is far below the margin): pdf 0, as the margin is all pdf() adds.
template <typename T, typename Sampler>
void check_outside(const Sampler& s, const std::vector<dvec3>& p, const std::string& name) {
    const double sign = ltc::solid_angle(p.data(), p.size()) > 0 ? 1 : -1;
    const double margin = static_cast<double>(ltc::detail::sample_margin<T>());
    for (std::size_t i = 0; i < p.size(); ++i) {
        const dvec3 a = glm::normalize(p[i]), b = glm::normalize(p[(i + 1) % p.size()]);
        const dvec3 n = sign * glm::normalize(glm::cross(a, b));
        const glm::vec<3, T> w(glm::normalize(glm::normalize(a + b) - 3 * margin * n));
        INFO(name << ", edge " << i);
        CHECK(s.pdf(w) == T(0));
    }
}

}  // namespace

TEST_CASE("solid-angle samplers: the reported sample next to an edge has pdf 1 / solid angle",
          "[sampler-edges][solid-angle-sampling]") {
    const std::vector<glm::vec3> v = edge_shapes()[0].v;
    const ltc::spherical_polygon_sampler<float> s(v.data(), v.size());
    const glm::vec3 w = s.sample(glm::vec2(0.256566316f, 0.999875903f));
    INFO("w = (" << w.x << ", " << w.y << ", " << w.z << "), pdf " << s.pdf(w) << ", 1 / solid angle "
                 << 1 / s.solid_angle());
    CHECK(s.pdf(w) == 1 / s.solid_angle());
}

TEMPLATE_TEST_CASE("solid-angle samplers: every sample of a 2000 x 2000 grid and the borders has pdf > 0",
                   "[sampler-edges][solid-angle-sampling]", float, double) {
    using T = TestType;
    const std::vector<glm::vec<2, T>> us = sweep<T>(2000);
    for (const shape& sh : edge_shapes()) {
        const std::vector<glm::vec<3, T>> v = as<T>(sh.v);
        const std::vector<dvec3> p(v.begin(), v.end());
        const ltc::spherical_polygon_sampler<T> poly(v.data(), v.size());
        REQUIRE_FALSE(poly.empty());
        check_pdf_of_samples<T>(poly, us, "polygon sampler, " + sh.name);
        check_outside<T>(poly, p, "polygon sampler, " + sh.name);
        if (v.size() == 3) {
            using ltc::detail::safe_normalize;
            const ltc::spherical_triangle_sampler<T> tri(safe_normalize(v[0]), safe_normalize(v[1]),
                                                         safe_normalize(v[2]));
            check_pdf_of_samples<T>(tri, us, "triangle sampler, " + sh.name);
            check_outside<T>(tri, p, "triangle sampler, " + sh.name);
        }
    }
}
