// The samplers at their edges (ltc/core/spherical_triangle_sampling.hpp,
// spherical_polygon_sampling.hpp, projected_solid_angle_sampling.hpp, ltc_polygon_sampling.hpp):
//   (a) every sample of the solid-angle samplers has pdf > 0 (a renderer divides by it): the
//       reported triangle and u, and a 2000 x 2000 grid of u plus the borders of the square, on
//       that triangle, a 1e-5 rad quad and larger shapes; directions a few margins outside an edge
//       still have pdf 0; in both precisions, with and without the wide rebuild (Wide = T);
//   (b) at the 1e-5 rad quad in float, the samplers' normalizations (the solid angle, E, I_D) and
//       the densities of their samples against independent long double references on the same
//       float input (and, for the LTC, the same float M^-1).
// Every input is exact in float (the references see the same numbers).
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/ltc_polygon_sampling.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>
#include <ltc/core/spherical_polygon_sampling.hpp>
#include <ltc/core/spherical_triangle_sampling.hpp>
#include <ltc/core/transformed.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace ltc_test_sampler_edges {  // the file's own names, apart from the other files of a unity batch

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

/// The reported sample: pdf(w) == 1 / solid_angle() (it was 0), rebuilt in double or not.
template <typename Sampler>
void check_reported(const Sampler& s) {
    const glm::vec3 w = s.sample(glm::vec2(0.256566316f, 0.999875903f));
    INFO("widened " << s.widened() << ": w = (" << w.x << ", " << w.y << ", " << w.z << "), pdf " << s.pdf(w)
                    << ", 1 / solid angle " << 1 / s.solid_angle());
    CHECK(s.pdf(w) == 1 / s.solid_angle());
}

TEST_CASE("solid-angle samplers: the reported sample next to an edge has pdf 1 / solid angle",
          "[sampler-edges][solid-angle-sampling]") {
    const std::vector<glm::vec3> v = edge_shapes()[0].v;
    check_reported(ltc::spherical_polygon_sampler<float>(v.data(), v.size()));
    check_reported(ltc::spherical_polygon_sampler<float, 8, float>(v.data(), v.size()));
}

TEMPLATE_TEST_CASE("solid-angle samplers: every sample of a 2000 x 2000 grid and the borders has pdf > 0",
                   "[sampler-edges][solid-angle-sampling]", float, double) {
    using T = TestType;
    const std::vector<glm::vec<2, T>> us = sweep<T>(2000);
    for (const shape& sh : edge_shapes()) {
        const std::vector<glm::vec<3, T>> v = as<T>(sh.v);
        const std::vector<dvec3> p(v.begin(), v.end());
        const ltc::spherical_polygon_sampler<T> poly(v.data(), v.size());
        const ltc::spherical_polygon_sampler<T, 8, T> narrow(v.data(), v.size());  // never widened
        REQUIRE_FALSE(poly.empty());
        REQUIRE_FALSE(narrow.empty());
        check_pdf_of_samples<T>(poly, us, "polygon sampler, " + sh.name);
        check_outside<T>(poly, p, "polygon sampler, " + sh.name);
        if (poly.widened()) {
            check_pdf_of_samples<T>(narrow, us, "polygon sampler in T, " + sh.name);
            check_outside<T>(narrow, p, "polygon sampler in T, " + sh.name);
        }
        if (v.size() == 3) {
            using ltc::detail::safe_normalize;
            const ltc::spherical_triangle_sampler<T> tri(safe_normalize(v[0]), safe_normalize(v[1]),
                                                         safe_normalize(v[2]));
            check_pdf_of_samples<T>(tri, us, "triangle sampler, " + sh.name);
            check_outside<T>(tri, p, "triangle sampler, " + sh.name);
        }
    }
}

namespace {

// (b) The references: long double (64-bit significand) on the float input, with no code of the
// library. For a polygon of size h the formulas lose 1 / h (the triple product, the edge terms
// of size h that cancel to E ~ h^2): 1e5 x 2^-64 ~ 1e-14 relative at h = 1e-5, far below the
// float tolerances.
using ld = long double;
struct lvec {
    ld x, y, z;
};
ld dot(const lvec& a, const lvec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
lvec cross(const lvec& a, const lvec& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
lvec unit(const lvec& a) {
    const ld l = std::sqrt(dot(a, a));
    return {a.x / l, a.y / l, a.z / l};
}
lvec to_ld(const glm::vec3& v) { return {v.x, v.y, v.z}; }
lvec times(const glm::mat3& m, const lvec& p) {  // m p with m's float entries (glm: m[column][row])
    return {ld(m[0][0]) * p.x + ld(m[1][0]) * p.y + ld(m[2][0]) * p.z,
            ld(m[0][1]) * p.x + ld(m[1][1]) * p.y + ld(m[2][1]) * p.z,
            ld(m[0][2]) * p.x + ld(m[1][2]) * p.y + ld(m[2][2]) * p.z};
}

/// |solid angle|: the fan from vertex 0, tan(Omega / 2) = a.(b x c) / (1 + a.b + b.c + c.a).
ld solid_angle_ref(const std::vector<lvec>& p) {
    ld s = 0;
    const lvec a = unit(p[0]);
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
        const lvec b = unit(p[k]), c = unit(p[k + 1]);
        s += 2 * std::atan2(dot(a, cross(b, c)), 1 + dot(a, b) + dot(b, c) + dot(c, a));
    }
    return std::abs(s);
}

/// E = int_P w.z dw for a polygon above the horizon: Lambert, |sum_i theta_i (a x b).z / |a x b|| / 2.
ld projected_ref(const std::vector<lvec>& p) {
    ld s = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        REQUIRE(p[i].z > 0);  // no clipping
        const lvec a = unit(p[i]), b = unit(p[(i + 1) % p.size()]), n = cross(a, b);
        const ld sn = std::sqrt(dot(n, n));
        s += std::atan2(sn, dot(a, b)) * n.z / sn;
    }
    return std::abs(s) / 2;
}

/// True where the unit w is inside every edge's great circle of p but by margin (the sine).
bool inside_ref(const std::vector<lvec>& p, const lvec& w, ld margin) {
    const ld sign = dot(unit(p[0]), cross(unit(p[1]), unit(p[2]))) > 0 ? 1 : -1;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const lvec n = unit(cross(unit(p[i]), unit(p[(i + 1) % p.size()])));
        if (sign * dot(w, n) < -margin) return false;
    }
    return true;
}

const ld kPi = 3.141592653589793238462643383279502884L;

}  // namespace

// (b) The 1e-5 rad quad in float (all three samplers rebuild it in double). Tolerances, u = 2^-24:
//   - the solid angle, E: the rounding of the double value to float, u, plus the double fan's
//     error, ~66 cond u_double ~ 1e-9 with cond ~ 1 / h = 1e5 (projected_triangle::condition),
//     below 0.1 u: 2 u; I_D = E / pi in float: E's, pi's and the division's 3 u; all <= 2 eps;
//   - the density of each sample against the reference at the returned float direction:
//     the solid-angle sampler's pdf is 1 / the solid angle (2 eps + u); the projected sampler's
//     w.z / E (E's 2 eps, the division and w.z's rounding 2 u): 4 eps for both; the LTC's is
//     evaluated from the float direction through M^-1 and its Jacobian in float, whose
//     rounding the float polygon (1e-5 rad) does not amplify: held to the header's 2^-12;
//   - the samples of the solid-angle and projected samplers are inside the reference polygon
//     to 4 eps (rounded from double, u, and renormalized in float, 2 u).
TEST_CASE("float samplers at a 1e-5 rad quad: normalizations and densities against long double",
          "[sampler-edges][solid-angle-sampling][projected-sampling][ltc-sampling]") {
    const std::vector<glm::vec3> q = edge_shapes()[1].v;
    std::vector<lvec> p;
    for (const glm::vec3& v : q) p.push_back(to_ld(v));
    const double eps = std::numeric_limits<float>::epsilon(), promise = 1.0 / 4096;
    const std::vector<glm::vec2> us = sweep<float>(64);

    const ld omega = solid_angle_ref(p), E = projected_ref(p);
    const ltc::spherical_polygon_sampler<float> solid(q.data(), q.size());
    const ltc::projected_polygon_sampler<float> cosine(q.data(), q.size());
    const double solid_error = double(std::abs(solid.solid_angle() - omega) / omega);
    const double e_error = double(std::abs(cosine.projected_solid_angle() - E) / E);
    double solid_pdf = 0, cosine_pdf = 0;
    long solid_outside = 0, cosine_outside = 0;
    for (const glm::vec2& u : us) {
        const glm::vec3 w = solid.sample(u);
        solid_pdf = std::max(solid_pdf, double(std::abs(solid.pdf(w) * omega - 1)));
        solid_outside += !inside_ref(p, to_ld(w), 4 * eps);
        const ltc::polygon_sample<float> x = cosine.sample(u);
        cosine_pdf = std::max(cosine_pdf, double(std::abs(x.pdf * E / ld(x.direction.z) - 1)));
        cosine_outside += !inside_ref(p, to_ld(x.direction), 4 * eps);
    }
    INFO("solid angle " << solid.solid_angle() << " (widened " << solid.widened() << "), reference "
                        << double(omega) << ": relative error " << solid_error << "; pdf " << solid_pdf << ", "
                        << solid_outside << " samples outside");
    INFO("E " << cosine.projected_solid_angle() << " (widened " << cosine.widened() << "), reference " << double(E)
              << ": relative error " << e_error << "; pdf " << cosine_pdf << ", " << cosine_outside
              << " samples outside");
    CHECK(solid_error <= 2 * eps);
    CHECK(e_error <= 2 * eps);
    CHECK(solid_pdf <= 4 * eps);
    CHECK(cosine_pdf <= 4 * eps);
    CHECK(solid_outside == 0);
    CHECK(cosine_outside == 0);

    // A generic M^-1 (no zero entry, det 1.9), exact in float; the quad stays above the horizon.
    const glm::mat3 m_inv(glm::vec3(1.75f, 0.25f, -0.3125f), glm::vec3(0.125f, 1.25f, 0.0625f),
                          glm::vec3(0.375f, -0.25f, 0.875f));  // columns
    const auto d = ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(m_inv);
    const ltc::ltc_polygon_sampler<float> lobe(d, q.data(), q.size());
    std::vector<lvec> r;
    for (const lvec& v : p) r.push_back(times(m_inv, v));
    const ld I = projected_ref(r) / kPi;
    const ld det = ld(m_inv[0][0]) * (ld(m_inv[1][1]) * m_inv[2][2] - ld(m_inv[2][1]) * m_inv[1][2]) -
                   ld(m_inv[1][0]) * (ld(m_inv[0][1]) * m_inv[2][2] - ld(m_inv[2][1]) * m_inv[0][2]) +
                   ld(m_inv[2][0]) * (ld(m_inv[0][1]) * m_inv[1][2] - ld(m_inv[1][1]) * m_inv[0][2]);
    const double i_error = double(std::abs(lobe.integral() - I) / I);
    double lobe_pdf = 0;
    for (const glm::vec2& u : us) {
        const ltc::polygon_sample<float> x = lobe.sample(u);
        // D(w) = D_o(w_o) |M^-1| / |M^-1 w|^3, D_o = max(0, w_o.z) / pi, w_o = M^-1 w / |M^-1 w|.
        const lvec mw = times(m_inv, to_ld(x.direction));
        const ld l = std::sqrt(dot(mw, mw));
        const ld density = std::max(ld(0), mw.z / l) / kPi * std::abs(det) / (l * l * l) / I;
        lobe_pdf = std::max(lobe_pdf, double(std::abs(x.pdf / density - 1)));
    }
    INFO("I_D " << lobe.integral() << ", reference " << double(I) << ": relative error " << i_error << "; pdf "
                << lobe_pdf);
    CHECK(i_error <= 2 * eps);
    CHECK(lobe_pdf <= promise);
}

}  // namespace ltc_test_sampler_edges
