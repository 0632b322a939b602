// Solid-angle sampling (ltc/core/spherical_triangle_sampling.hpp, spherical_polygon_sampling.hpp)
// in float and double; every triangle goes through both samplers:
//   (a) chi-square goodness of fit against exact bin probabilities (sub-triangles of the fan);
//   (b) sample -> invert round trip, within the rounding of both carried through the Jacobian;
//   (c) pdf: integral over the sphere = 1 (Monte Carlo, 4 sigma), pdf * solid_angle = 1 exactly inside;
//   (d) tiny, near-hemisphere, grazing, thin and nearly collinear shapes: finite unit samples,
//       inside up to the margin; empty input: finite unit samples, pdf 0.
// Shapes have dyadic coordinates, exact in float. Every random sequence has a fixed seed.
#include "support/chi_square.hpp"
#include "support/rng.hpp"

#include <ltc/core/solid_angle.hpp>
#include <ltc/core/spherical_polygon_sampling.hpp>
#include <ltc/core/spherical_triangle_sampling.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace ltc_test_solid_angle_sampling {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dvec2, glm::dvec3;

template <typename T>
const double eps = static_cast<double>(std::numeric_limits<T>::epsilon());

// Inside margin, in eps of T (u = eps / 2). A sample is within 35 u of the triangle: c' leaves the
// arc a c by e's error (8 u: stable_cross, cross, normalize) and the sum's 3 u; the tangent at b
// 8 u; cos and sin of the arc from b 9 u; the last sum 3 u, normalize 4 u. The polygon sampler's
// unit vertices move its edges by 4 u; the test's normals and dot, in double, 7 u: 46 u = 23 eps.
constexpr double margin_eps = 24;
// Round trip: |u' - u| <= (35 u of sample + 26 u of invert: its rounding as a move of w) amp
// |J|_F + 12 u (the ratios u.x = A' / A, u.y = |w - b|^2 / |c' - b|^2, the polygon's rescale).
// amp = 1 / cos(d / 2), d the largest arc from the apex b: the tangent at b towards c' and b x w
// lose that when c' or w is nearly -b (the near-hemisphere square's v_0 v_2: 178.7 deg, amp 90).
constexpr double round_trip_jacobian_eps = 32, round_trip_eps = 6;

using ltc_test::chi_square_critical_1e4;

struct shape {  // regular shapes are in (a) - (c) too
    std::string name;
    std::vector<dvec3> v;
    bool regular;
};

/// The shapes of (d); `tiny`: the tiny ones' edge (2^-10 ~ 1e-3 rad in float, 2^-14 in double).
std::vector<shape> shapes(double tiny) {
    const double g = std::ldexp(1.0, -20), t = 0.125 + tiny, s = 0.25 + tiny, h = 1.0 / 64;
    return {
        {"triangle", {{0, 0, 1}, {1, 0, 0.25}, {0, 1, 0.5}}, true},
        {"triangle, other winding", {{0, 1, 0.5}, {1, 0, 0.25}, {0, 0, 1}}, true},
        {"near-hemisphere triangle", {{1, 0, h}, {-0.5, 0.875, h}, {-0.5, -0.875, 1}}, true},
        {"small triangle", {{0.25, 0.125, 1}, {0.25 + 1.0 / 128, 0.125, 1}, {0.25, 0.125 + 1.0 / 128, 1}}, true},
        {"tiny triangle", {{0.25, 0.125, 1}, {s, 0.125, 1}, {0.25, t, 1}}, true},
        {"square", {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}, true},
        {"tilted pentagon",
         {{1, 0, 1.25}, {0.25, 1, 1.0625}, {-0.75, 0.5, 0.8125}, {-0.75, -0.5, 0.8125}, {0.25, -1, 1.0625}}, true},
        {"octagon, other winding",
         {{-.5, 1, 2}, {.5, 1, 2}, {1, .5, 2}, {1, -.5, 2}, {.5, -1, 2}, {-.5, -1, 2}, {-1, -.5, 2}, {-1, .5, 2}},
         true},
        {"near-hemisphere square", {{-64, -64, 1}, {64, -64, 1}, {64, 64, 1}, {-64, 64, 1}}, true},
        {"tiny square", {{0.25, 0.125, 1}, {s, 0.125, 1}, {s, t, 1}, {0.25, t, 1}}, true},
        {"grazing triangle", {{0.5, -0.5, g}, {1, 0, g}, {0.5, 0.5, g}}, false},
        {"grazing quad", {{0.5, -0.5, -g}, {1, -0.5, -g}, {1, 0.5, -g}, {0.5, 0.5, -g}}, false},
        {"thin sliver", {{-1, 0, 1}, {1, 0, 1}, {0, 1.0 / 4096, 1}}, false},
        {"long lune", {{1, 0, 0}, {0, 1.0 / 1024, 1}, {-1, 1.0 / 1024, 0}}, false},
        {"nearly collinear triangle", {{0, 0, 1}, {1, 0, 1}, {0.5, g, 1}}, false},
        {"square, a collinear vertex", {{-1, -1, 1}, {0, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}, false},
        {"square, a nearly collinear vertex", {{-1, -1, 1}, {0, -1 - g, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}, false},
    };
}

/// One sampler under test: spherical_triangle_sampler on the unit vertices (triangles only) or
/// spherical_polygon_sampler on the shape's vertices.
template <typename T>
struct sampler {
    using vec3 = glm::vec<3, T>;
    bool triangle;
    std::string name;
    std::vector<vec3> v;  // what the sampler was given
    ltc::spherical_triangle_sampler<T> tri;
    ltc::spherical_polygon_sampler<T> poly{nullptr, 0};

    template <typename U>
    sampler(const std::vector<glm::vec<3, U>>& p, bool as_triangle, const std::string& shape_name)
        : triangle(as_triangle), name((as_triangle ? "triangle sampler, " : "polygon sampler, ") + shape_name) {
        for (const auto& q : p) v.push_back(triangle ? ltc::detail::safe_normalize(vec3(q)) : vec3(q));
        if (triangle) tri = ltc::spherical_triangle_sampler<T>(v[0], v[1], v[2]);
        else poly = ltc::spherical_polygon_sampler<T>(v.data(), v.size());
    }
    T solid_angle() const { return triangle ? tri.solid_angle() : poly.solid_angle(); }
    vec3 sample(const glm::vec<2, T>& u) const { return triangle ? tri.sample(u) : poly.sample(u); }
    T pdf(const vec3& w) const { return triangle ? tri.pdf(w) : poly.pdf(w); }
    glm::vec<2, T> invert(const vec3& w) const { return triangle ? tri.invert(w) : poly.invert(w); }
    std::vector<dvec3> plane() const { return {v.begin(), v.end()}; }  // projects to the sampled set
};

/// The samplers of every shape (the regular ones), in T and in double (the same geometry).
template <typename T>
std::vector<std::pair<sampler<T>, sampler<double>>> cases(bool regular_only) {
    std::vector<std::pair<sampler<T>, sampler<double>>> c;
    for (const shape& s : shapes(sizeof(T) == sizeof(float) ? 1.0 / 1024 : 1.0 / 16384))
        for (const bool as_triangle : {true, false})
            if (!(as_triangle && s.v.size() != 3) && !(regular_only && !s.regular)) {
                const sampler<T> st(s.v, as_triangle, s.name);
                c.emplace_back(st, sampler<double>(st.plane(), as_triangle, s.name));
            }
    return c;
}

/// Inward unit normals of the great circles of the polygon's edges (double; none for a repeated
/// vertex), and the signed distance of unit w from them (> 0 inside).
std::vector<dvec3> edge_normals(const std::vector<dvec3>& p) {
    const double s = ltc::solid_angle(p.data(), p.size()) > 0 ? 1.0 : -1.0;
    std::vector<dvec3> n;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const dvec3 a = glm::normalize(p[i]), b = glm::normalize(p[(i + 1) % p.size()]);
        n.push_back(s * ltc::detail::safe_normalize(ltc::detail::stable_cross(a, b, glm::dot(a, b))));
        if (n.back() == dvec3(0)) n.pop_back();
    }
    return n;
}
double depth(const std::vector<dvec3>& normals, const dvec3& w) {
    double d = std::numeric_limits<double>::infinity();
    for (const dvec3& n : normals) d = std::min(d, glm::dot(w, n));
    return d;
}

/// amp of the round trip: 2 / |b + x| for x the point of the polygon's edges farthest from the
/// apex b (an end of an edge, or where its arc passes nearest to -b).
double antipodal_amplification(const std::vector<dvec3>& P, const dvec3& b) {
    double lo = 1;  // the smallest b.x
    for (std::size_t i = 0; i < P.size(); ++i) {
        const dvec3 p = glm::normalize(P[i]), q = glm::normalize(P[(i + 1) % P.size()]);
        const dvec3 n = ltc::detail::safe_normalize(glm::cross(p, q));
        const dvec3 m = ltc::detail::safe_normalize(glm::dot(b, n) * n - b);
        lo = std::min(lo, glm::dot(b, p));
        if (glm::dot(glm::cross(p, m), n) > 0 && glm::dot(glm::cross(m, q), n) > 0) lo = std::min(lo, glm::dot(b, m));
    }
    return 2 / std::sqrt(std::max(2 + 2 * lo, 1e-300));
}

}  // namespace

// (a) Bins: the fan triangles from vertex 0 split at their edges' midpoints into 4, 16, ... (on the
// parents' great circles: they tile the polygon) until >= 64; a sample goes to the bin it is
// deepest in. Probability = bin solid angle / the sum, which must match ltc::solid_angle within
// 1e-6 (a probability error d moves X^2 by ~N d^2). Expected counts >= 5 (Cochran); X^2 below the
// p = 1e-4 critical value. Samples' rounding (<= 24 eps, 1e-4 of a tiny float edge) is negligible.
// (c) X = 4 pi pdf(w), w uniform on the sphere: mean 1, variance 4 pi / Omega - 1; 4 sigma plus
// Omega's rounding in T (<= 4 eps), for Omega >= 0.05 (>= 1000 hits).
TEMPLATE_TEST_CASE("solid-angle sampling: chi-square test against exact bin probabilities; pdf integrates to 1",
                   "[solid-angle-sampling]", float, double) {
    using T = TestType;
    constexpr int N = 1 << 18;
    ltc_test::rng rng(0x5a5a0000ull + sizeof(T));
    for (const auto& c : cases<T>(true)) {
        const std::vector<dvec3> P = c.first.plane();
        std::vector<std::array<dvec3, 3>> bins;
        for (std::size_t i = 1; i + 1 < P.size(); ++i)
            bins.push_back({glm::normalize(P[0]), glm::normalize(P[i]), glm::normalize(P[i + 1])});
        const auto mid = [](const dvec3& x, const dvec3& y) { return glm::normalize(x + y); };
        while (bins.size() < 64)
            for (std::size_t i = 0, n = bins.size(); i < n; ++i) {
                const std::array<dvec3, 3> t = bins[i], m = {mid(t[0], t[1]), mid(t[1], t[2]), mid(t[2], t[0])};
                bins[i] = m;
                bins.insert(bins.end(), {{t[0], m[0], m[2]}, {m[0], t[1], m[1]}, {m[2], m[1], t[2]}});
            }
        std::vector<std::vector<dvec3>> normals;
        std::vector<double> expected;
        double total = 0, x2 = 0;
        for (const auto& t : bins) {
            normals.push_back(edge_normals({t.begin(), t.end()}));
            total += expected.emplace_back(std::abs(ltc::triangle_solid_angle(t[0], t[1], t[2])));
        }
        for (double& e : expected) e *= N / total;
        std::vector<long> observed(bins.size(), 0);
        for (int n = 0; n < N; ++n) {
            const dvec3 w(c.first.sample(rng.uniform2<T>()));
            std::size_t best = 0;  // the first bin that contains w, else the one it is deepest in
            double deepest = depth(normals[0], w);
            for (std::size_t b = 1; b < bins.size() && deepest < 0; ++b)
                if (depth(normals[b], w) > deepest) deepest = depth(normals[best = b], w);
            ++observed[best];
        }
        for (std::size_t b = 0; b < bins.size(); ++b) x2 += std::pow(observed[b] - expected[b], 2) / expected[b];
        const int dof = static_cast<int>(bins.size()) - 1;
        const double omega = std::abs(ltc::solid_angle(P.data(), P.size())), pi = ltc::pi<double>();
        double sum = 0;  // (c)
        for (int n = 0; omega >= 0.05 && n < N; ++n)
            sum += 4 * pi * static_cast<double>(c.first.pdf(glm::vec<3, T>(rng.direction())));
        INFO(c.first.name << ", solid angle " << omega << ": X^2 = " << x2 << " with " << dof << " dof, critical "
                          << chi_square_critical_1e4(dof) << "; mean of 4 pi pdf " << sum / N);
        CHECK(*std::min_element(expected.begin(), expected.end()) >= 5);
        CHECK(std::abs(total / omega - 1) <= 1e-6);
        CHECK(x2 < chi_square_critical_1e4(dof));
        if (omega >= 0.05) CHECK(std::abs(sum / N - 1) <= 4 * std::sqrt((4 * pi / omega - 1) / N) + 4 * eps<T>);
    }
}

// (b) u on a jittered 32 x 32 grid of [1/64, 63/64]^2 (away from u.y = 0, the apex where every u.x
// meets). |J|_F: the Jacobian of the double sampler's invert at w, by central differences of
// step 1e-5 sqrt(solid angle) (the shape's size).
TEMPLATE_TEST_CASE("solid-angle sampling: invert(sample(u)) == u within the rounding through the Jacobian",
                   "[solid-angle-sampling]", float, double) {
    using T = TestType;
    ltc_test::rng rng(0x1e7e0000ull + sizeof(T));
    for (const auto& c : cases<T>(true)) {
        const std::vector<dvec3> P = c.first.plane();
        const double h = 1e-5 * std::sqrt(static_cast<double>(c.first.solid_angle()));
        const double amp = antipodal_amplification(P, glm::normalize(P[c.first.triangle ? 1 : 0]));
        long failures = 0;
        double worst = 0;  // |u' - u| / tolerance
        for (int i = 0; i < 32 * 32; ++i) {
            const glm::vec<2, T> u(static_cast<T>((1 + 62 * (i / 32 + rng.uniform()) / 32) / 64),
                                   static_cast<T>((1 + 62 * (i % 32 + rng.uniform()) / 32) / 64));
            const glm::vec<3, T> w = c.first.sample(u);
            const glm::vec<2, T> diff = glm::abs(c.first.invert(w) - u);  // in T: no double round trip of u
            double j2 = 0;
            for (int a = 0; a < 3; ++a) {
                const dvec3 dw = h * dvec3(a == 0, a == 1, a == 2), wd(w);
                const dvec2 du = c.second.invert(glm::normalize(wd + dw)) - c.second.invert(glm::normalize(wd - dw));
                j2 += glm::dot(du, du) / (4 * h * h);
            }
            const double tol = (round_trip_jacobian_eps * amp * std::sqrt(j2) + round_trip_eps) * eps<T>;
            const double err = std::max(static_cast<double>(diff.x), static_cast<double>(diff.y));
            worst = std::max(worst, err / tol);
            failures += !(err <= tol);
        }
        INFO(c.first.name << ": largest |u' - u| / tolerance " << worst << " (amp " << amp << ")");
        CHECK(failures == 0);
    }
}

// (d) and (c)'s exact check: u on 64 x 64 random points and the corners 0 and the largest value
// below 1. Unit length within 2 eps (safe_normalize: 4 u); inside up to margin_eps; pdf(w) either 0
// or 1 / solid_angle(), the latter farther than the margin from every edge; pdf(-w) = 0; invert
// in [0, 1]^2 (so finite).
TEMPLATE_TEST_CASE("solid-angle sampling: tiny, huge, grazing, thin and degenerate shapes give unit samples inside",
                   "[solid-angle-sampling]", float, double) {
    using T = TestType;
    ltc_test::rng rng(0xd3d30000ull + sizeof(T));
    const T one = T(1) - std::numeric_limits<T>::epsilon() / 2;
    for (const auto& c : cases<T>(false)) {
        const sampler<T>& s = c.first;
        const std::vector<dvec3> normals = edge_normals(s.plane());
        std::vector<glm::vec<2, T>> us = {{0, 0}, {0, one}, {one, 0}, {one, one}};
        for (int i = 0; i < 64 * 64; ++i) us.push_back(rng.uniform2<T>());
        long not_unit = 0, outside = 0, wrong_pdf = 0, bad_invert = 0;
        double worst = -1e300;  // largest distance outside, in eps
        for (const auto& u : us) {
            const glm::vec<3, T> w = s.sample(u);
            not_unit += !(std::abs(glm::length(dvec3(w)) - 1) <= 2 * eps<T>);
            const double inside = depth(normals, dvec3(w));
            worst = std::max(worst, -inside / eps<T>);
            outside += !(inside >= -margin_eps * eps<T>);
            const T p = s.pdf(w), uniform = T(1) / s.solid_angle();
            wrong_pdf += !(p == uniform || (p == T(0) && inside <= margin_eps * eps<T>)) || s.pdf(-w) != T(0);
            const glm::vec<2, T> v = s.invert(w);
            bad_invert += !(v.x >= T(0) && v.x <= T(1) && v.y >= T(0) && v.y <= T(1));
        }
        INFO(s.name << ", solid angle " << s.solid_angle() << ": largest distance outside " << worst << " eps");
        CHECK(s.solid_angle() > T(0));
        CHECK(not_unit == 0);
        CHECK(outside == 0);
        CHECK(wrong_pdf == 0);
        CHECK(bad_invert == 0);
    }
}

TEMPLATE_TEST_CASE("solid-angle sampling: empty polygons sample a finite unit direction with pdf 0",
                   "[solid-angle-sampling]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    const std::vector<vec3> nine(9, vec3(0, 0, 1)), two = {{0, 0, 1}, {1, 0, 1}};
    const std::vector<vec3> at_origin = {{0, 0, 1}, {1, 0, 1}, {0, 0, 0}}, edge_on = {{1, 0, 1}, {2, 0, 1}, {2, 0, 2}};
    const std::vector<vec3> collinear = {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}, {3, 0, 1}};
    for (const auto* p : {&nine, &two, &at_origin, &edge_on, &collinear}) {
        const ltc::spherical_polygon_sampler<T> s(p->data(), p->size());
        const vec3 w = s.sample(glm::vec<2, T>(T(0.5)));
        CAPTURE(p->size(), w.x, w.y, w.z);
        CHECK(s.empty());
        CHECK(s.solid_angle() == T(0));
        CHECK(std::abs(glm::length(dvec3(w)) - 1) <= 2 * eps<T>);
        CHECK(s.pdf(w) == T(0));
        CHECK(s.invert(w) == glm::vec<2, T>(T(0)));
    }
    const ltc::spherical_triangle_sampler<T> flat(vec3(0, 0, 1), vec3(0, 0, 1), vec3(1, 0, 0));  // samples a
    CHECK((flat.empty() && flat.sample(glm::vec<2, T>(T(0.5))) == vec3(0, 0, 1) && flat.pdf(vec3(0, 0, 1)) == T(0)));
}

}  // namespace ltc_test_solid_angle_sampling
