// ltc/core/projected_solid_angle_sampling.hpp, part 2: invert() against sample() both ways, pdf()
// against the samples and over the sphere, and degenerate input. The polygons and their bounds:
// support/polygon_sampling.hpp and test_projected_sampling.cpp (part 1).
#include "support/polygon_sampling.hpp"
#include "support/rng.hpp"

#include <ltc/core/polygon.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ltc_test_projected_sampling_inverse {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::polygon_sampling;

namespace {

template <typename T>
double eps() {
    return std::numeric_limits<T>::epsilon();
}

/// Allowed |invert(sample(u)) - u| per component. u.x = (cdf_k-1 + F_k(psi)) / E: the psi solve
/// stops within 4 eps max(mass, scale) of its target (scale, the sum of the edge terms'
/// magnitudes, is below the triangle's share of the bound), F errs by up to that share when
/// sample() evaluates it and again when invert() does, and the cdf by the bound: <= 4 bound / E.
/// u.y = W(s) / W(L(psi)) is held to the same budget (W's terms are the same z-weighted arcs), and
/// 16 eps covers the divisions, clamps and the rounding of the direction read back. Measured:
/// <= 0.03 of this in both precisions.
template <typename T>
double u_tolerance(const projected_fixture<T>& f) {
    return 4 * f.bound / f.E + 16 * eps<T>();
}

/// Angular margin of pdf()'s containment (8 eps on each great circle) plus the directions of the
/// vertices the sampler computes (crossing points, normalization), with room: directions farther
/// than this inside have pdf > 0, farther outside pdf 0.
template <typename T>
double containment_margin(const poly& p) {
    const std::vector<double> d = clip(exact(p), dvec3(0, 0, 1)).delta;
    return eps<T>() * (64 + *std::max_element(d.begin(), d.end()));
}

}  // namespace

TEMPLATE_TEST_CASE("projected sampler: invert(sample(u)) == u", "[projected-sampling][invert]", float, double) {
    using T = TestType;
    ltc_test::rng rng(0x1e7e00000001ull + sizeof(T));
    for (const projected_fixture<T>& f : projected_fixtures<T>()) {
        const double tol = u_tolerance(f);
        double worst = 0;
        long out_of_square = 0;
        for (int i = 0; i < 4096; ++i) {
            // away from the square's borders, where the apex and the zero-density horizon are
            const glm::vec<2, T> u = T(1) / T(64) + (T(62) / T(64)) * rng.uniform2<T>();
            const glm::vec<2, T> v = f.s.invert(f.s.sample(u).direction);
            if (!(v.x >= 0 && v.x <= 1 && v.y >= 0 && v.y <= 1)) ++out_of_square;
            worst = std::max({worst, std::abs(double(v.x - u.x)), std::abs(double(v.y - u.y))});
        }
        INFO(f.name << ": largest |invert(sample(u)) - u| = " << worst << ", tolerance " << tol);
        CHECK(worst <= tol);
        CHECK(out_of_square == 0);
    }
}

// w inside: a random convex combination of the vertices (weights -log u), normalized and rounded
// to T, with w.z >= 0.01: next to the zero-density horizon the map u -> w is singular (there,
// in float, u.x = 1 - 4e-8 and 1 are 0.1 rad apart). Tolerance: |dw/du.x| + |dw/du.y| (central
// differences, step 1e-6, of the double sampler on the same vertices) times u_tolerance, + 16
// eps for the direction's own rounding. Measured: <= 0.03 of it.
TEMPLATE_TEST_CASE("projected sampler: sample(invert(w)) == w", "[projected-sampling][invert]", float, double) {
    using T = TestType;
    ltc_test::rng rng(0x1e7e00000101ull + sizeof(T));
    int polygons = 0;
    for (const projected_fixture<T>& f : projected_fixtures<T>()) {
        const ltc::projected_polygon_sampler<double> sd(f.p.data(), f.p.size());
        const auto at = [&](const glm::dvec2& u) {
            return sd.sample(glm::clamp(u, glm::dvec2(0), glm::dvec2(1))).direction;
        };
        double worst = 0;
        int used = 0;
        for (int i = 0; i < 2048; ++i) {
            std::vector<double> weight(f.p.size());
            double sum = 0;
            for (double& x : weight) sum += x = -std::log(1 - rng.uniform());
            dvec3 x(0);
            for (std::size_t k = 0; k < f.p.size(); ++k) x += weight[k] / sum * f.p[k];
            const glm::vec<3, T> w(glm::normalize(x));
            if (!(w.z >= T(0.01))) continue;
            ++used;
            const glm::vec<2, T> u = f.s.invert(w);
            const double err = glm::length(dvec3(f.s.sample(u).direction) - dvec3(w));
            const glm::dvec2 ud(u), hx(1e-6, 0), hy(0, 1e-6);
            const double jx = glm::length(at(ud + hx) - at(ud - hx)) / 2e-6;
            const double jy = glm::length(at(ud + hy) - at(ud - hy)) / 2e-6;
            worst = std::max(worst, err / ((jx + jy) * u_tolerance(f) + 16 * eps<T>()));
        }
        polygons += used > 0 ? 1 : 0;
        INFO(f.name << ": " << used << " directions, largest |sample(invert(w)) - w| / tolerance = " << worst);
        CHECK(worst <= 1);
    }
    CHECK(polygons >= 16);  // all but the two grazing straddling quads (z < 0.01 throughout)
}

// pdf(sample(u).direction) == sample(u).pdf exactly (both w.z / E; the containment margin
// keeps the sample in), and > 0. Over the sphere: 2^18 uniform directions w, 4 pi pdf(w) has
// mean 1 (pdf integrates to 1) within 4 standard errors (sigma from the estimate's own sample
// variance) plus bound / E for E's rounding, for the polygons subtending >= 0.05 sr (smaller
// ones are hit too rarely for the variance estimate). On the way: pdf == 0 wherever w is outside
// the polygon or below the horizon by containment_margin, pdf > 0 inside by that margin.
TEMPLATE_TEST_CASE("projected sampler: pdf() matches the samples and integrates to 1", "[projected-sampling][pdf]",
                   float, double) {
    using T = TestType;
    ltc_test::rng rng(0x1e7e00000201ull + sizeof(T));
    int integrated = 0;
    for (const projected_fixture<T>& f : projected_fixtures<T>()) {
        long mismatch = 0, zero = 0;
        for (int i = 0; i < 4096; ++i) {
            const ltc::polygon_sample<T> x = f.s.sample(rng.uniform2<T>());
            if (!(x.pdf > 0)) ++zero;
            if (!(f.s.pdf(x.direction) == x.pdf)) ++mismatch;
        }
        INFO(f.name << ": " << zero << " samples with pdf 0, " << mismatch << " with pdf(direction) != pdf");
        CHECK(zero == 0);
        CHECK(mismatch == 0);

        const double margin = containment_margin<T>(f.p);
        const bool integrate = ltc::clipped_solid_angle(f.p.data(), f.p.size()) >= 0.05 ||
                               ltc::clipped_solid_angle(f.p.data(), f.p.size()) <= -0.05;
        const long n = integrate ? 1 << 18 : 1 << 14;
        double s1 = 0, s2 = 0;
        long wrong_outside = 0, wrong_inside = 0;
        for (long i = 0; i < n; ++i) {
            const dvec3 wd = rng.direction();
            const glm::vec<3, T> w(wd);
            const double p = double(f.s.pdf(w));
            const double x = 4 * kPi * p;
            s1 += x, s2 += x * x;
            if ((wd.z < -margin || !inside(f.p, wd, -margin)) && p != 0) ++wrong_outside;
            if (wd.z > margin && inside(f.p, wd, margin) && !(p > 0)) ++wrong_inside;
        }
        INFO(wrong_outside << " directions outside with pdf != 0, " << wrong_inside << " inside with pdf 0");
        CHECK(wrong_outside == 0);
        CHECK(wrong_inside == 0);
        if (!integrate) continue;
        ++integrated;
        const double mean = s1 / double(n), sigma = std::sqrt((s2 / double(n) - mean * mean) / double(n));
        INFO("Monte Carlo integral of pdf: " << mean << " +- " << sigma);
        CHECK(std::abs(mean - 1) <= 4 * sigma + f.bound / f.E + 8 * eps<T>());
    }
    CHECK(integrated >= 10);
}

namespace {

/// The checks every sample of a non-empty sampler must pass: finite, unit within 4 eps
/// (safe_normalize: <= 4u, plus the lift's renormalization), inside the polygon within
/// containment_margin, z > 0, pdf > 0 and pdf(direction) == pdf.
template <typename T, std::size_t Max>
bool good_sample(const ltc::projected_polygon_sampler<T, Max>& s, const poly& p, const glm::vec<2, T>& u) {
    const ltc::polygon_sample<T> x = s.sample(u);
    const dvec3 w(x.direction);
    return std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z) &&
           std::abs(glm::length(w) - 1) <= 4 * eps<T>() && w.z > 0 && inside(p, w, -containment_margin<T>(p)) &&
           x.pdf > 0 && s.pdf(x.direction) == x.pdf;
}

}  // namespace

// Degenerate input (the header's list): n < 3, n > MaxVertices, a vertex at the origin, a
// polygon below the horizon or in its plane give an empty sampler: E = 0, pdf() 0, and sample()
// the normal with pdf 0. Tiny, near-hemisphere, grazing and near-degenerate polygons (slivers, a
// repeated vertex, a vertex on an edge, the polygons scaled by 2^-60 and 2^60) give good samples
// (good_sample) for u at the corners and on the borders of [0, 1]^2 (0, the smallest subnormal,
// 1/2, the largest value below 1, and 1, which the sampler clamps) and for random u.
TEMPLATE_TEST_CASE("projected sampler: degenerate input", "[projected-sampling][degenerate]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    using vec2 = glm::vec<2, T>;
    const auto empty_ok = [](const ltc::projected_polygon_sampler<T>& s) {
        const ltc::polygon_sample<T> x = s.sample(vec2(T(0.3), T(0.7)));
        return s.empty() && s.projected_solid_angle() == 0 && s.pdf(vec3(0, 0, 1)) == 0 &&
               x.direction == vec3(0, 0, 1) && x.pdf == 0 && s.invert(vec3(0, 0, 1)) == vec2(0);
    };
    const std::vector<vec3> quad = as<T>(rect(dvec3(0.2, 0.1, 1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 0.4));
    for (std::size_t n = 0; n < 3; ++n) CHECK(empty_ok(ltc::projected_polygon_sampler<T>(quad.data(), n)));
    const std::vector<vec3> nine = as<T>(ngon(dvec3(0, 0, 1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 9));
    CHECK(empty_ok(ltc::projected_polygon_sampler<T>(nine.data(), 9)));
    CHECK_FALSE(ltc::projected_polygon_sampler<T, 9>(nine.data(), 9).empty());
    std::vector<vec3> at_origin = quad;
    at_origin[2] = vec3(0);
    CHECK(empty_ok(ltc::projected_polygon_sampler<T>(at_origin.data(), 4)));
    const std::vector<vec3> below = as<T>(rect(dvec3(0.2, 0.1, -1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 0.4));
    CHECK(empty_ok(ltc::projected_polygon_sampler<T>(below.data(), 4)));
    const std::vector<vec3> in_horizon = as<T>(rect(dvec3(0.2, 1, 0), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 0.4));
    CHECK(empty_ok(ltc::projected_polygon_sampler<T>(in_horizon.data(), 4)));

    std::vector<named_polygon> polygons;
    for (const projected_fixture<T>& f : projected_fixtures<T>()) polygons.push_back({f.name, f.p});
    const poly q = rounded<T>(rect(dvec3(0.2, 0.1, 1), dvec3(1, 0, 0), dvec3(0, 1, 0), 0.5, 0.4));
    polygons.push_back({"repeated vertex", {q[0], q[1], q[1], q[2], q[3]}});
    polygons.push_back({"vertex on an edge", rounded<T>({q[0], 0.5 * (q[0] + q[1]), q[1], q[2], q[3]})});
    for (const double scale : {0x1p-60, 0x1p60}) {
        poly scaled;
        for (const dvec3& v : polygons[4].v) scaled.push_back(scale * v);  // the straddling quad
        polygons.push_back({"straddling quad scaled", scaled});
    }
    const std::vector<T> edge = {T(0), std::numeric_limits<T>::denorm_min(), T(0.5),
                                 T(1) - std::numeric_limits<T>::epsilon() / 2, T(1)};
    ltc_test::rng rng(0x1e7e00000301ull + sizeof(T));
    for (const named_polygon& np : polygons) {
        const std::vector<vec3> v = as<T>(np.v);
        const ltc::projected_polygon_sampler<T> s(v.data(), v.size());
        REQUIRE_FALSE(s.empty());
        long bad = 0;
        vec2 first_bad(-1);
        std::vector<vec2> us;
        for (const T x : edge)
            for (const T y : edge) us.push_back(vec2(x, y));
        for (int i = 0; i < 1024; ++i) us.push_back(rng.uniform2<T>());
        for (const vec2& u : us)
            if (!good_sample(s, np.v, u) && bad++ == 0) first_bad = u;
        INFO(np.name << ": " << bad << " bad samples, the first at u = (" << first_bad.x << ", " << first_bad.y << ")");
        CHECK(bad == 0);
    }
}

// Regression (found by this test): a triangle small enough that E is subnormal gave a non-empty
// sampler whose pdf w.z / E overflowed to +Inf (sample(u).pdf and pdf()): in float the triangle (0, 0, 1),
// (h, 0, 1), (0, h, 1) with h = 1e-20 (E = 5e-41) or 1e-22 (E = 5.6e-45); in double h = 1e-160.
// (h = 1e-19 gives E = 5e-39 and pdf 2e38, still finite; h = 1e-25 an empty sampler.) Either
// outcome, empty or a finite pdf, is acceptable; +Inf is not (f / pdf = 0, weights Inf / Inf).
TEMPLATE_TEST_CASE("projected sampler: sub-epsilon triangles give an empty sampler or a finite pdf",
                   "[projected-sampling][degenerate]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    const std::vector<double> sizes =
        sizeof(T) == sizeof(float) ? std::vector<double>{1e-19, 1e-20, 1e-22} : std::vector<double>{1e-150, 1e-160};
    for (const double h : sizes) {
        const vec3 v[3] = {vec3(0, 0, 1), vec3(T(h), 0, 1), vec3(0, T(h), 1)};
        const ltc::projected_polygon_sampler<T> s(v, 3);
        const ltc::polygon_sample<T> x = s.sample(glm::vec<2, T>(T(0.5), T(0.5)));
        INFO("h = " << h << ": empty " << s.empty() << ", E " << double(s.projected_solid_angle()) << ", pdf "
                    << double(x.pdf) << ", pdf() " << double(s.pdf(x.direction)));
        CHECK((s.empty() || (std::isfinite(x.pdf) && x.pdf > 0)));
        CHECK(std::isfinite(s.pdf(x.direction)));
    }
}

// Regression (found by the fuzzer): a planar quad with a vertex exactly on the horizon clips to
// three vertices on the horizon's great circle, so one fan triangle is flat (mass 0). With u.x = 1
// the triangle search ended on it when it came last, and the sample was its apex, on the horizon,
// with pdf 0; flat triangles are now never chosen.
TEMPLATE_TEST_CASE("projected sampler: a flat last fan triangle is never sampled", "[projected-sampling][degenerate]",
                   float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    const vec3 q[4] = {vec3(-1, 1, -1), vec3(1, 1, -1), vec3(1, 1, 0), vec3(-1, 1, 1)};
    for (int reversed = 0; reversed < 2; ++reversed)
        for (int rotation = 0; rotation < 4; ++rotation) {
            vec3 v[4];
            for (int i = 0; i < 4; ++i) v[i] = q[(rotation + (reversed ? 4 - i : i)) % 4];
            const ltc::projected_polygon_sampler<T> s(v, 4);
            REQUIRE_FALSE(s.empty());
            for (const T y : {T(0), T(0.25), T(0.5), T(1)}) {
                const ltc::polygon_sample<T> x = s.sample(glm::vec<2, T>(T(1), y));
                CAPTURE(reversed, rotation, y);
                CHECK(x.pdf > 0);
                CHECK(s.pdf(x.direction) > 0);
            }
        }
}

}  // namespace ltc_test_projected_sampling_inverse
