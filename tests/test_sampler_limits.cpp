// The polygon samplers' capacity (ltc/core/spherical_polygon_sampling.hpp,
// projected_solid_angle_sampling.hpp, ltc_polygon_sampling.hpp, polygon_area_sampling.hpp): each
// holds at most max_vertices = MaxVertices vertices (fixed storage, host and device code). The
// convention, tested here for each of the four:
//   (a) checked() throws ltc::invalid_polygon for n > max_vertices (naming n, max_vertices and the
//       capacity that holds them), n < 3 and a vertex not finite, and otherwise gives the plain
//       constructor's sampler (the same bits), empty() where the geometry holds nothing to sample;
//   (b) the plain constructor above max_vertices (a precondition) gives the documented empty()
//       state: normalization 0, samples with pdf 0 and pdf() 0, never an Inf or NaN;
//   (c) a larger MaxVertices holds larger polygons (12- and 16-gons, one crossing the horizon):
//       normalizations against the closed forms in double, every sample of a grid of u and the
//       square's borders has pdf() > 0 equal to the pdf it carries, and E[f / pdf] = int_P f for
//       a bounded f / pdf (Monte Carlo, fixed seeds, 4 sigma); the capacity changes no bit for
//       polygons that fit the smaller one.
#include "support/rng.hpp"

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/invalid_polygon.hpp>
#include <ltc/core/ltc_polygon_sampling.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/core/polygon_area_sampling.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>
#include <ltc/core/spherical_polygon_sampling.hpp>
#include <ltc/core/squared_clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ltc_test_sampler_limits {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dvec3;
constexpr double kPi = 3.141592653589793238462643383279502884;

/// A regular n-gon of the given radius about `centre` in the plane spanned by the unit vectors ex,
/// ey, rounded to T (the double references use the rounded vertices).
template <typename T>
std::vector<glm::vec<3, T>> ngon(const dvec3& centre, const dvec3& ex, const dvec3& ey, double radius, std::size_t n) {
    std::vector<glm::vec<3, T>> v;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = 2 * kPi * double(i) / double(n);
        v.emplace_back(centre + radius * (std::cos(t) * ex + std::sin(t) * ey));
    }
    return v;
}

template <typename T>
std::vector<dvec3> widened(const std::vector<glm::vec<3, T>>& v) {
    return {v.begin(), v.end()};
}

/// A GGX-like lobe's M^-1 (row-major [a 0 b; 0 c 0; d 0 1]), entries exact in float.
template <typename T>
glm::mat<3, 3, T> lobe_m_inv() {
    return glm::mat<3, 3, T>(glm::transpose(glm::dmat3(0.625, 0, 0.125, 0, 0.5, 0, -0.25, 0, 1)));
}

/// u of the sweep: the centres of a k x k grid and k points on each border of the square.
template <typename T>
std::vector<glm::vec<2, T>> sweep(int k) {
    const T one = T(1) - std::numeric_limits<T>::epsilon() / 2;
    std::vector<glm::vec<2, T>> u;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) u.emplace_back(T((i + 0.5) / k), T((j + 0.5) / k));
    for (int i = 0; i < k; ++i) {
        const T t = T(double(i) / k);
        u.insert(u.end(), {{T(0), t}, {one, t}, {t, T(0)}, {t, one}});
    }
    return u;
}

/// Mean and standard error of f(u) over N values of u (fixed seed).
struct estimate {
    double mean, sigma;
};
template <typename T, typename F>
estimate mean_of(std::uint64_t seed, F f) {
    constexpr long N = 1 << 16;
    ltc_test::rng g(seed);
    double s = 0, s2 = 0;
    for (long i = 0; i < N; ++i) {
        const double y = f(g.uniform2<T>());
        s += y, s2 += y * y;
    }
    const double mean = s / N;
    return {mean, std::sqrt(std::max(0.0, s2 / N - mean * mean) / N)};
}

template <typename F>
std::string thrown(F f) {
    try {
        f();
    } catch (const ltc::invalid_polygon& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEMPLATE_TEST_CASE("sampler limits: checked() throws invalid_polygon for n > max_vertices, n < 3, non-finite vertices",
                   "[sampler-limits]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    using D = ltc::transformed<ltc::clamped_cosine<T>>;
    const D d = D::from_inverse(lobe_m_inv<T>());
    STATIC_REQUIRE(ltc::spherical_polygon_sampler<T>::max_vertices == 8);
    STATIC_REQUIRE(ltc::projected_polygon_sampler<T>::max_vertices == 8);
    STATIC_REQUIRE(ltc::ltc_polygon_sampler<T>::max_vertices == 8);
    STATIC_REQUIRE(ltc::polygon_area_sampler<T>::max_vertices == 8);
    STATIC_REQUIRE(ltc::ltc_polygon_sampler<T, 12>::max_vertices == 12);
    const auto nine = ngon<T>(dvec3(0.1, -0.2, 1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 9);
    const auto eight = ngon<T>(dvec3(0.1, -0.2, 1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 8);
    std::vector<vec3> not_finite = eight;
    not_finite[5].y = std::numeric_limits<T>::quiet_NaN();

    const auto check_all = [&](const char* name, auto make) {
        INFO(name);
        const std::string many = thrown([&] { make(nine.data(), 9); });
        CHECK_THAT(many, Catch::Contains(std::string(name) + ": 9 vertices") && Catch::Contains("max_vertices = 8") &&
                             Catch::Contains("<T, 9>"));
        CHECK_THAT(thrown([&] { make(eight.data(), 2); }), Catch::Contains("2 vertices, a polygon has at least 3"));
        CHECK_THAT(thrown([&] { make(not_finite.data(), 8); }), Catch::Contains("vertex 5 is not finite"));
        CHECK(thrown([&] { make(eight.data(), 8); }).empty());
    };
    check_all("ltc::spherical_polygon_sampler",
              [](const vec3* v, std::size_t n) { return ltc::spherical_polygon_sampler<T>::checked(v, n); });
    check_all("ltc::projected_polygon_sampler",
              [](const vec3* v, std::size_t n) { return ltc::projected_polygon_sampler<T>::checked(v, n); });
    check_all("ltc::ltc_polygon_sampler",
              [&](const vec3* v, std::size_t n) { return ltc::ltc_polygon_sampler<T>::checked(d, v, n); });
    check_all("ltc::polygon_area_sampler",
              [](const vec3* v, std::size_t n) { return ltc::polygon_area_sampler<T>::checked(v, n); });
    // The capacity of a larger sampler is its own.
    CHECK_THAT(thrown([&] {
                   const auto thirteen = ngon<T>(dvec3(0, 0, 1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 13);
                   ltc::ltc_polygon_sampler<T, 12>::checked(d, thirteen.data(), 13);
               }),
               Catch::Contains("13 vertices, more than its max_vertices = 12"));

    // Accepted input: the plain constructor's sampler, bit for bit; a polygon with nothing to
    // sample (below the horizon) is no error and stays empty().
    const auto s = ltc::ltc_polygon_sampler<T>::checked(d, eight.data(), 8);
    const auto plain = ltc::ltc_polygon_sampler<T>(d, eight.data(), 8);
    REQUIRE_FALSE(s.empty());
    CHECK(s.integral() == plain.integral());
    const glm::vec<2, T> u(T(0.3), T(0.7));
    CHECK(s.sample(u).direction == plain.sample(u).direction);
    CHECK(ltc::projected_polygon_sampler<T>::checked(eight.data(), 8).projected_solid_angle() ==
          ltc::projected_polygon_sampler<T>(eight.data(), 8).projected_solid_angle());
    CHECK(ltc::spherical_polygon_sampler<T>::checked(eight.data(), 8).solid_angle() ==
          ltc::spherical_polygon_sampler<T>(eight.data(), 8).solid_angle());
    CHECK(ltc::polygon_area_sampler<T>::checked(eight.data(), 8).area() ==
          ltc::polygon_area_sampler<T>(eight.data(), 8).area());
    const auto below = ngon<T>(dvec3(0, 0, -1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 6);
    CHECK(ltc::projected_polygon_sampler<T>::checked(below.data(), 6).empty());
    CHECK(ltc::ltc_polygon_sampler<T>::checked(D::from_inverse(glm::mat<3, 3, T>(T(1))), below.data(), 6).empty());
}

TEMPLATE_TEST_CASE("sampler limits: the plain constructor above max_vertices gives the documented empty state",
                   "[sampler-limits]", float, double) {
    using T = TestType;
    using vec2 = glm::vec<2, T>;
    const auto d = ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(lobe_m_inv<T>());
    const auto nine = ngon<T>(dvec3(0.1, -0.2, 1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 9);
    REQUIRE(d.integrate(nine.data(), 9) > T(0));  // a polygon D does see
    const vec2 u(T(0.3), T(0.7));

    const ltc::ltc_polygon_sampler<T> lobe(d, nine.data(), 9);
    CHECK(lobe.empty());
    CHECK(lobe.integral() == T(0));
    CHECK(lobe.sample(u).pdf == T(0));
    CHECK(lobe.pdf(lobe.sample(u).direction) == T(0));
    CHECK(ltc::detail::is_finite(lobe.sample(u).direction));

    const ltc::projected_polygon_sampler<T> cosine(nine.data(), 9);
    CHECK(cosine.empty());
    CHECK(cosine.projected_solid_angle() == T(0));
    CHECK(cosine.sample(u).pdf == T(0));
    CHECK(cosine.pdf(cosine.sample(u).direction) == T(0));

    const ltc::spherical_polygon_sampler<T> solid(nine.data(), 9);
    CHECK(solid.empty());
    CHECK(solid.solid_angle() == T(0));
    CHECK(solid.pdf(solid.sample(u)) == T(0));
    CHECK(ltc::detail::is_finite(solid.sample(u)));

    const ltc::polygon_area_sampler<T> area(nine.data(), 9);
    CHECK(area.empty());
    CHECK(area.area() == T(0));
    CHECK(area.solid_angle_pdf(glm::vec<3, T>(T(0)), area.sample(u)) == T(0));
}

TEMPLATE_TEST_CASE("sampler limits: a larger MaxVertices holds 12- and 16-gons; every sample has pdf > 0",
                   "[sampler-limits]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    constexpr std::size_t cap = 16;
    const double eps = std::numeric_limits<T>::epsilon();
    const auto d = ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(lobe_m_inv<T>());
    const auto ref = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(glm::dmat3(lobe_m_inv<T>()));
    struct polygon {
        const char* name;
        std::vector<vec3> v;
    };
    const dvec3 tilted = glm::normalize(dvec3(0, 1, 0.4));
    const polygon polygons[] = {
        {"overhead 12-gon", ngon<T>(dvec3(0.2, -0.1, 1.2), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.6, 12)},
        {"16-gon crossing the horizon", ngon<T>(dvec3(-0.3, 0.2, 0.05), dvec3(1, 0, 0), tilted, 0.7, 16)},
    };
    std::uint64_t seed = sizeof(T) == sizeof(float) ? 0x5a3100 : 0x5a3200;
    for (const polygon& p : polygons) {
        INFO(p.name);
        const std::size_t n = p.v.size();
        const std::vector<dvec3> pd = widened(p.v);
        // Where the polygon crosses the horizon, of the shading frame and of the cosine's space.
        std::size_t below = 0, below_lobe = 0;
        for (const dvec3& x : pd) below += x.z < 0, below_lobe += (glm::dmat3(lobe_m_inv<T>()) * x).z < 0;
        CHECK((below == 0) == (below_lobe == 0));
        CAPTURE(below, below_lobe);
        const auto us = sweep<T>(200);

        // The LTC restricted to the polygon: I_D against the closed form in double, on the same
        // M^-1 and vertices. The closed form's and the sampler's rounding: both O(n) edge terms
        // of a few eps each on a well-conditioned polygon; 64 n eps of I_D bounds them.
        const ltc::ltc_polygon_sampler<T, cap> lobe(d, p.v.data(), n);
        REQUIRE_FALSE(lobe.empty());
        const double i_d = ref.integrate(pd.data(), n);
        CHECK(std::abs(double(lobe.integral()) - i_d) <= 64 * double(n) * eps * i_d);
        long zero = 0, mismatch = 0;
        for (const auto& u : us) {
            const auto x = lobe.sample(u);
            zero += !(x.pdf > T(0));
            mismatch += lobe.pdf(x.direction) != x.pdf;
        }
        CHECK(zero == 0);
        CHECK(mismatch == 0);

        // The clamped cosine restricted to the polygon: E = pi x the clipped form factor.
        const ltc::projected_polygon_sampler<T, cap> cosine(p.v.data(), n);
        REQUIRE_FALSE(cosine.empty());
        const double e = kPi * std::abs(ltc::form_factor_signed(pd.data(), n));
        CHECK(std::abs(double(cosine.projected_solid_angle()) - e) <= 64 * double(n) * eps * e);
        zero = mismatch = 0;
        for (const auto& u : us) {
            const auto x = cosine.sample(u);
            zero += !(x.pdf > T(0));
            mismatch += cosine.pdf(x.direction) != x.pdf;
        }
        CHECK(zero == 0);
        CHECK(mismatch == 0);

        // Uniform in solid angle: the solid angle itself.
        const ltc::spherical_polygon_sampler<T, cap> solid(p.v.data(), n);
        REQUIRE_FALSE(solid.empty());
        const double omega = std::abs(ltc::solid_angle(pd.data(), n));
        CHECK(std::abs(double(solid.solid_angle()) - omega) <= 64 * double(n) * eps * omega);
        zero = 0;
        for (const auto& u : us) zero += !(solid.pdf(solid.sample(u)) > T(0));
        CHECK(zero == 0);

        // Uniform by area: the regular n-gon's area, n r^2 sin(2 pi / n) / 2.
        const ltc::polygon_area_sampler<T, cap> area(p.v.data(), n);
        REQUIRE_FALSE(area.empty());
        const double r = glm::length(pd[0] - (pd[0] + pd[n / 2]) / 2.0);
        const double a = double(n) * r * r * std::sin(2 * kPi / double(n)) / 2;
        CHECK(std::abs(double(area.area()) - a) <= 64 * double(n) * eps * a);
        zero = 0;
        for (const auto& u : us) zero += !(area.solid_angle_pdf(vec3(T(0)), area.sample(u)) > T(0));
        CHECK(zero == 0);

        // The distributions: E[f / pdf] = int_P f for an f bounded by a multiple of the density
        // (so that f / pdf is bounded and 4 sigma of the sample means applies): the squared
        // cosine over each (for the LTC, D_2 of the same M: D_2 / D = 3 (M^-1 w).z / 2 / |M^-1 w|),
        // in the cosine's space, and the clamped cosine for the uniform sampler.
        const auto ref2 = ltc::transformed<ltc::squared_clamped_cosine<double>>::from_inverse(glm::dmat3(lobe_m_inv<T>()));
        const double i2_lobe = ref2.integrate(pd.data(), n);
        const double i2_up = 2 * kPi / 3 * ltc::squared_clamped_cosine<double>::integrate(pd.data(), n);
        const estimate el = mean_of<T>(seed++, [&](const glm::vec<2, T>& u) {
            const auto x = lobe.sample(u);
            return ref2.eval(dvec3(x.direction)) / double(x.pdf);
        });
        const estimate ec = mean_of<T>(seed++, [&](const glm::vec<2, T>& u) {
            const auto x = cosine.sample(u);
            const double z = std::max(0.0, double(x.direction.z));
            return z * z / double(x.pdf);
        });
        const estimate es = mean_of<T>(seed++, [&](const glm::vec<2, T>& u) {
            const vec3 w = solid.sample(u);
            return std::max(0.0, double(w.z)) / double(solid.pdf(w));
        });
        INFO("ltc " << el.mean << " +- " << el.sigma << " (" << i2_lobe << "), cosine " << ec.mean << " +- "
                    << ec.sigma << " (" << i2_up << "), solid " << es.mean << " +- " << es.sigma << " (" << e << ")");
        CHECK(std::abs(el.mean - i2_lobe) <= 4 * el.sigma + 64 * double(n) * eps * i2_lobe);
        CHECK(std::abs(ec.mean - i2_up) <= 4 * ec.sigma + 64 * double(n) * eps * i2_up);
        CHECK(std::abs(es.mean - e) <= 4 * es.sigma + 64 * double(n) * eps * e);
    }

    // The capacity changes no bit for a polygon that fits the smaller one (a pentagon crossing
    // the horizon).
    const auto five = ngon<T>(dvec3(-0.3, 0.2, 0.05), dvec3(1, 0, 0), tilted, 0.7, 5);
    REQUIRE(std::any_of(five.begin(), five.end(), [](const vec3& x) { return x.z < T(0); }));
    const glm::vec<2, T> u(T(0.3), T(0.7));
    const ltc::ltc_polygon_sampler<T> small(d, five.data(), 5);
    const ltc::ltc_polygon_sampler<T, cap> large(d, five.data(), 5);
    CHECK(small.integral() == large.integral());
    CHECK(small.sample(u).direction == large.sample(u).direction);
    CHECK(small.sample(u).pdf == large.sample(u).pdf);
    CHECK(ltc::spherical_polygon_sampler<T>(five.data(), 5).sample(u) ==
          ltc::spherical_polygon_sampler<T, cap>(five.data(), 5).sample(u));
}

}  // namespace ltc_test_sampler_limits
