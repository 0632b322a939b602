// ltc/core/polygon_area_sampling.hpp: uniform sampling of a convex planar polygon by area (the
// light-area sampling baseline) and its density in solid angle.
#include "support/polygon_sampling.hpp"
#include "support/rng.hpp"

#include <ltc/core/polygon_area_sampling.hpp>
#include <ltc/core/solid_angle.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace ltc_test_polygon_area_sampling {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::polygon_sampling;

namespace {

struct planar {
    dvec3 o, e1, e2;  // a point of the plane and an orthonormal basis of it
    glm::dvec2 at(const dvec3& x) const { return {glm::dot(x - o, e1), glm::dot(x - o, e2)}; }
};

planar frame_of(const poly& p) {
    const dvec3 n = facing_normal(p);
    const dvec3 e1 = glm::normalize(p[1] - p[0]);
    return {p[0], e1, glm::cross(n, e1)};
}

/// Shoelace area of a polygon given in plane coordinates (x, y, 1).
double area2d(const poly& q) {
    double a = 0;
    for (std::size_t i = 0; i < q.size(); ++i) a += q[i].x * q[(i + 1) % q.size()].y - q[(i + 1) % q.size()].x * q[i].y;
    return std::abs(a) / 2;
}

std::vector<named_polygon> area_polygons() {
    const dvec3 a = glm::normalize(dvec3(1, 0.2, 0.4)), b = glm::normalize(glm::cross(dvec3(0.3, -0.5, 1), a));
    return {{"quad", rect(dvec3(0.3, -0.2, 1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.4, 0.3)},
            {"tilted pentagon", ngon(dvec3(-0.4, 0.5, 1.2), a, b, 0.5, 5)},
            {"triangle", {dvec3(-0.5, 0.2, 1), dvec3(0.7, 0.25, 0.8), dvec3(0.1, 0.9, 1.4)}},
            {"long thin quad", rect(dvec3(0.2, 0.1, 1), a, b, 2, 0.01)}};
}

}  // namespace

// Uniform by area: the points, in the plane's coordinates, binned on an 8 x 8 grid over the
// polygon's bounding box; a cell's probability is the exact area of the polygon clipped to the cell (clipped in
// homogeneous plane coordinates (x, y, 1), shoelace) over the area: chi-square as in
// test_projected_sampling.cpp (N = 2^16, p = 1e-4 critical value, fixed seeds). area() against the
// shoelace area within 16 n eps (the fan's cross products and square roots, a few u per
// triangle), the sample mean against the centroid within 4 sigma (sigma from the samples'
// variance) + 8 eps (the samples' rounding), and every point in the plane within 8 eps |x|.
TEMPLATE_TEST_CASE("area sampler: uniform by area", "[area-sampling]", float, double) {
    using T = TestType;
    constexpr long N = 1 << 16;
    const double eps = std::numeric_limits<T>::epsilon();
    std::uint64_t seed = 0xa4ea00000001ull + (sizeof(T) == sizeof(float) ? 0x100 : 0x200);
    for (const named_polygon& np : area_polygons())
        for (const poly& p : {rounded<T>(np.v), rounded<T>(reversed(np.v))}) {
            const std::vector<glm::vec<3, T>> v = as<T>(p);
            const ltc::polygon_area_sampler<T> s(v.data(), v.size());
            const planar f = frame_of(p);
            poly flat;  // (x, y, 1)
            double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
            for (const dvec3& x : p) {
                const glm::dvec2 q = f.at(x);
                flat.push_back(dvec3(q, 1));
                x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
            }
            const double area = area2d(flat);
            const int k = 8;
            std::vector<double> prob;
            for (int i = 0; i < k * k; ++i) {
                const double xa = x0 + (x1 - x0) * (i / k) / k, xb = x0 + (x1 - x0) * (i / k + 1) / k;
                const double ya = y0 + (y1 - y0) * (i % k) / k, yb = y0 + (y1 - y0) * (i % k + 1) / k;
                clipped c = exact(flat);
                for (const dvec3& n : {dvec3(1, 0, -xa), dvec3(-1, 0, xb), dvec3(0, 1, -ya), dvec3(0, -1, yb)})
                    c = clip(c, n);
                prob.push_back(c.v.size() < 3 ? 0 : area2d(c.v) / area);
            }
            std::vector<long> observed(k * k, 0);
            dvec3 centroid(0), mean(0), mean2(0);
            for (std::size_t i = 1; i + 1 < p.size(); ++i)
                centroid += glm::length(glm::cross(p[i] - p[0], p[i + 1] - p[0])) / 2 * (p[0] + p[i] + p[i + 1]) / 3.0;
            centroid /= area;
            long off_plane = 0;
            ltc_test::rng rng(seed++);
            for (long i = 0; i < N; ++i) {
                const dvec3 x(s.sample(rng.uniform2<T>()));
                const glm::dvec2 q = f.at(x);
                const auto index = [&](double t, double lo, double hi) {
                    return std::min(std::max(int(std::floor((t - lo) / (hi - lo) * k)), 0), k - 1);
                };
                ++observed[index(q.x, x0, x1) * k + index(q.y, y0, y1)];
                mean += x, mean2 += x * x;
                if (std::abs(glm::dot(x - p[0], facing_normal(p))) > 8 * eps * glm::length(x)) ++off_plane;
            }
            mean /= double(N), mean2 /= double(N);
            const chi_square x = chi_square_test(prob, observed, N);
            INFO(np.name << ": area() " << s.area() << " vs " << area << "; X^2 = " << x.x2 << " with " << x.dof
                         << " dof (critical " << x.critical << ")");
            CHECK(std::abs(double(s.area()) - area) <= 16 * p.size() * eps * area);
            CHECK(x.dof >= 8);
            CHECK(x.x2 < x.critical);
            CHECK(off_plane == 0);
            for (int c = 0; c < 3; ++c) {
                const double sigma = std::sqrt(std::max(mean2[c] - mean[c] * mean[c], 0.0) / N);
                CHECK(std::abs(mean[c] - centroid[c]) <= 4 * sigma + 8 * eps * glm::length(centroid));
            }
        }
}

// solid_angle_pdf, the density of normalize(x - o) for x uniform on P, integrates to 1 over P's
// spherical image: (i) E[1 / pdf] over the samples is the solid angle Omega of P seen from o
// (Van Oosterom's closed form in double, ltc::solid_angle); (ii) over 2^18 uniform directions w,
// 4 pi pdf(o, x(w)) (x(w) the ray's hit on P, 0 when it misses) has mean 1. Both within 4 standard
// errors (from the samples' own variance) + 1e-6 (|Omega| rounding, float pdf ~ 10 eps relative).
TEMPLATE_TEST_CASE("area sampler: solid_angle_pdf integrates to 1 over the polygon's image",
                   "[area-sampling]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    std::uint64_t seed = 0xa4ea00000401ull + (sizeof(T) == sizeof(float) ? 0x100 : 0x200);
    for (const named_polygon& np : area_polygons())
        for (const dvec3 origin : {dvec3(0), dvec3(0.2, -0.1, 0.3)}) {
            const poly p = rounded<T>(np.v);
            const std::vector<vec3> v = as<T>(p);
            const ltc::polygon_area_sampler<T> s(v.data(), v.size());
            poly seen;
            for (const dvec3& x : p) seen.push_back(x - origin);
            const double omega = std::abs(ltc::solid_angle(seen.data(), seen.size()));
            ltc_test::rng rng(seed++);
            double s1 = 0, s2 = 0, t1 = 0, t2 = 0;
            const long n = 1 << 16, m = 1 << 18;
            for (long i = 0; i < n; ++i) {
                const vec3 x = s.sample(rng.uniform2<T>());
                const double y = 1 / double(s.solid_angle_pdf(vec3(origin), x));
                s1 += y, s2 += y * y;
            }
            const dvec3 normal = facing_normal(seen);
            for (long i = 0; i < m; ++i) {
                const dvec3 w = rng.direction();
                double y = 0;
                if (inside(seen, w, 0)) {
                    const dvec3 hit = origin + glm::dot(seen[0], normal) / glm::dot(w, normal) * w;
                    y = 4 * kPi * double(s.solid_angle_pdf(vec3(origin), vec3(hit)));
                }
                t1 += y, t2 += y * y;
            }
            const double mean_i = s1 / n, sigma_i = std::sqrt((s2 / n - mean_i * mean_i) / n);
            const double mean_ii = t1 / m, sigma_ii = std::sqrt((t2 / m - mean_ii * mean_ii) / m);
            INFO(np.name << " from (" << origin.x << ", " << origin.y << ", " << origin.z << "): E[1 / pdf] " << mean_i
                         << " +- " << sigma_i << " vs Omega " << omega << "; 4 pi E[pdf] " << mean_ii << " +- "
                         << sigma_ii);
            CHECK(std::abs(mean_i - omega) <= 4 * sigma_i + 1e-6 * omega);
            CHECK(std::abs(mean_ii - 1) <= 4 * sigma_ii + 1e-6);
        }
}

// Degenerate input (the header's list): n < 3, n > MaxVertices and zero area (collinear or
// coincident vertices) give an empty sampler: area 0, finite samples (vertex 0; the origin for
// n = 0), density 0. A direction in the polygon's plane (origin in the plane) has density 0, not
// Inf; points of polygons at 2^+-30 scale are finite with positive densities (any scale: the test
// case after this one).
TEMPLATE_TEST_CASE("area sampler: degenerate input", "[area-sampling][degenerate]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    using vec2 = glm::vec<2, T>;
    const std::vector<vec3> quad = as<T>(rect(dvec3(0.2, 0.1, 1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 0.4));
    const auto empty_ok = [&](const ltc::polygon_area_sampler<T>& s, const vec3& first) {
        const vec3 x = s.sample(vec2(T(0.3), T(0.6)));
        return s.empty() && s.area() == 0 && x == first && s.solid_angle_pdf(vec3(0), x) == 0 &&
               s.solid_angle_pdf(vec3(0), quad[0]) == 0;
    };
    for (std::size_t n = 0; n < 3; ++n)
        CHECK(empty_ok(ltc::polygon_area_sampler<T>(quad.data(), n), n == 0 ? vec3(0) : quad[0]));
    const std::vector<vec3> nine = as<T>(ngon(dvec3(0, 0, 1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 9));
    CHECK(empty_ok(ltc::polygon_area_sampler<T>(nine.data(), 9), nine[0]));
    CHECK_FALSE(ltc::polygon_area_sampler<T, 9>(nine.data(), 9).empty());
    const std::vector<vec3> collinear = {vec3(0, 0, 1), vec3(1, 0, 1), vec3(2, 0, 1), vec3(3, 0, 1)};
    CHECK(empty_ok(ltc::polygon_area_sampler<T>(collinear.data(), 4), collinear[0]));
    const std::vector<vec3> same(4, vec3(T(0.5), T(0.5), T(1)));
    CHECK(empty_ok(ltc::polygon_area_sampler<T>(same.data(), 4), same[0]));

    const ltc::polygon_area_sampler<T> s(quad.data(), 4);
    const vec3 in_plane(T(0.2), T(0.1), T(1));  // the origin of the pdf in the polygon's plane z = 1
    CHECK(s.solid_angle_pdf(in_plane, s.sample(vec2(T(0.5)))) == 0);
    CHECK(s.solid_angle_pdf(s.sample(vec2(T(0.5))), s.sample(vec2(T(0.5)))) == 0);  // x at the origin
    for (const T scale : {T(0x1p-30), T(0x1p30)}) {
        std::vector<vec3> scaled;
        for (const vec3& x : quad) scaled.push_back(scale * x);
        const ltc::polygon_area_sampler<T> big(scaled.data(), 4);
        REQUIRE_FALSE(big.empty());
        for (const T u : {T(0), T(0.5), T(1)}) {
            const vec3 x = big.sample(vec2(u, T(1) - u));
            const T p = big.solid_angle_pdf(vec3(0), x);
            CHECK((std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)));
            CHECK((std::isfinite(p) && p > 0));
        }
    }
}

// Regression (found by this test): a polygon with nonzero area gave an empty sampler when its
// coordinates were large or small: the fan's |cross| = sqrt(dot(c, c)) (glm::length) over- or underflows at
// |c|^2 ~ |x|^4, i.e. for |x| beyond ~2^31 or below ~2^-31 in float (2^255 / 2^-255 in double),
// although the header promises an empty sampler for zero area only; and solid_angle_pdf's
// d2 sqrt(d2) = |x - o|^3 overflows or underflows even earlier (|x - o| ~ 2^42.7 or 2^-49.7 in
// float). The density of the direction to the polygon's centre is scale-invariant (x and o
// scaled alike), so it must equal the unscaled one (within 64 eps, the computations' rounding).
// Found: the quad below scaled by 2^45 or 2^-45 in float is empty() (area 0, pdf 0).
TEMPLATE_TEST_CASE("area sampler: any scale", "[area-sampling][degenerate]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    const std::vector<vec3> quad = as<T>(rect(dvec3(0.2, 0.1, 1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 0.4));
    const ltc::polygon_area_sampler<T> unit(quad.data(), 4);
    const vec3 centre(T(0.2), T(0.1), T(1));
    const double expected = double(unit.solid_angle_pdf(vec3(0), centre));
    const int e = sizeof(T) == sizeof(float) ? 45 : 300;
    for (const T scale : {std::ldexp(T(1), -e), std::ldexp(T(1), e)}) {
        std::vector<vec3> scaled;
        for (const vec3& x : quad) scaled.push_back(scale * x);
        const ltc::polygon_area_sampler<T> s(scaled.data(), 4);
        const double p = double(s.solid_angle_pdf(vec3(0), scale * centre));
        INFO("scale " << double(scale) << ": empty " << s.empty() << ", area " << double(s.area()) << ", pdf " << p
                      << " (unscaled " << expected << ")");
        CHECK_FALSE(s.empty());
        CHECK(std::abs(p - expected) <= 64 * std::numeric_limits<T>::epsilon() * expected);
    }
}

// Regression (found by the fuzzer): vertices with a coordinate at the largest finite float. The
// weighted sum b0 a + b1 b + b2 c of a sample rounded past it to +Inf; the sample is now clamped
// to the triangle's bounding box, which holds the exact point.
TEMPLATE_TEST_CASE("area sampler: vertices at the largest finite value", "[area-sampling][degenerate]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    using vec2 = glm::vec<2, T>;
    const T big = std::numeric_limits<T>::max();
    const std::vector<vec3> quad = {vec3(0, 0, big), vec3(1, 0, big), vec3(1, 1, big), vec3(0, 1, big)};
    const ltc::polygon_area_sampler<T> s(quad.data(), 4);
    REQUIRE_FALSE(s.empty());
    for (int i = 0; i <= 16; ++i)
        for (int j = 0; j <= 16; ++j) {
            const vec3 x = s.sample(vec2(T(i) / 16, T(j) / 16));
            CAPTURE(i, j);
            CHECK((std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)));
            CHECK(x.z == big);
        }
}

}  // namespace ltc_test_polygon_area_sampling
