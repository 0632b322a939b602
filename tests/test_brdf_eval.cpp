// Pointwise properties of the microfacet BRDF models of ltc/brdf (ggx, beckmann): reciprocity
// and mirror symmetry, the robust closed forms against the textbook ones, and degenerate input.
#include <ltc/brdf/beckmann.hpp>
#include <ltc/brdf/ggx.hpp>

#include <catch2/catch.hpp>

#include "support/brdf_references.hpp"
#include "support/rng.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ltc_test_brdf_eval {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::brdf_checks;  // configurations, references, LTC_BRDF_TYPES

// (f) reciprocity: rho(V, L) = rho(L, V), i.e. eval(V, L) / L.z == eval(L, V) / V.z. Both sides
// evaluate the same D (V + L == L + V exactly) and a G2 symmetric up to the order of two
// additions; with the divisions that is <= ~8 roundings per side: 16 eps_T relative. The pdf
// and eval are also even in L.y for V in the xz-plane (used by the quadrature references):
// the same bound.
TEMPLATE_TEST_CASE("brdf: reciprocity and mirror symmetry", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using T = typename B::scalar;
    using vec3 = glm::vec<3, T>;
    ltc_test::rng rng(20160724);
    const double tol = 16 * eps<T>();
    for (const double alpha : {0.0001, 0.05, 0.2, 0.5, 1.0, 3.0}) {
        const T a = static_cast<T>(alpha);
        for (int k = 0; k < 2000; ++k) {
            glm::dvec3 v = rng.direction(), l = rng.direction();
            v.z = std::abs(v.z), l.z = std::abs(l.z);
            const vec3 V(v), L(l);
            const double f = static_cast<double>(B::eval(V, L, a) / L.z);
            const double g = static_cast<double>(B::eval(L, V, a) / V.z);
            INFO(B::name << " alpha " << alpha << " V " << v.x << " " << v.y << " " << v.z << " L " << l.x
                         << " " << l.y << " " << l.z << ": " << f << " vs " << g);
            REQUIRE(std::isfinite(f));
            // (+ the smallest normal T: subnormal results have no relative precision)
            const double floor = static_cast<double>(std::numeric_limits<T>::min());
            REQUIRE(std::abs(f - g) <= tol * std::max(std::abs(f), std::abs(g)) + floor);
            const vec3 Vxz(V.x, T(0), V.z), Lm(L.x, -L.y, L.z);  // V in the xz-plane (not unit: scaled below)
            const vec3 Vn = Vxz / glm::length(Vxz);
            const double p1 = static_cast<double>(B::pdf(Vn, L, a)), p2 = static_cast<double>(B::pdf(Vn, Lm, a));
            const double e1 = static_cast<double>(B::eval(Vn, L, a)), e2 = static_cast<double>(B::eval(Vn, Lm, a));
            REQUIRE(std::abs(p1 - p2) <= tol * std::max(p1, p2) + floor);
            REQUIRE(std::abs(e1 - e2) <= tol * std::max(e1, e2) + floor);
        }
    }
}

// The robust closed forms of the headers against the textbook ones, in double, away from the
// cancellations that the textbook forms suffer (theta in [3, 87] degrees): relative 1e-10
// (the textbook -1 + sqrt(1 + x) loses up to eps / x ~ 1e-12 for x = alpha^2 tan^2 >= 5e-6).
TEST_CASE("brdf: the robust forms agree with the textbook formulas", "[brdf]") {
    using G = ltc::brdf::ggx<double>;
    using K = ltc::brdf::beckmann<double>;
    ltc_test::rng rng(42);
    const auto rel = [](double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); };
    for (const double a : {0.05, 0.2, 0.5, 1.0}) {
        for (int k = 0; k < 500; ++k) {
            glm::dvec3 V = rng.direction(), L = rng.direction();
            V.z = std::abs(V.z), L.z = std::abs(L.z);
            if (V.z < 0.05 || V.z > 0.9986 || L.z < 0.05 || L.z > 0.9986) continue;
            const glm::dvec3 h = glm::normalize(V + L);
            const double ch = h.z, t2h = (1 - ch * ch) / (ch * ch);
            const auto tan2 = [](const glm::dvec3& w) { return (1 - w.z * w.z) / (w.z * w.z); };
            // GGX
            const double Dg = a * a / (pi * std::pow(ch * ch * (a * a - 1) + 1, 2));
            const auto lam_g = [&](const glm::dvec3& w) { return (-1 + std::sqrt(1 + a * a * tan2(w))) / 2; };
            const double G2g = 1 / (1 + lam_g(V) + lam_g(L)), G1g = 1 / (1 + lam_g(V));
            CHECK(rel(G::ndf(h, a), Dg) < 1e-10);
            CHECK(rel(G::lambda(V, a), lam_g(V)) < 1e-10);
            CHECK(rel(G::g1(V, a), G1g) < 1e-10);
            CHECK(rel(G::g2(V, L, a), G2g) < 1e-10);
            CHECK(rel(G::eval(V, L, a), Dg * G2g / (4 * V.z)) < 1e-10);
            CHECK(rel(G::pdf(V, L, a), G1g * glm::dot(V, h) * Dg / V.z / (4 * glm::dot(V, h))) < 1e-10);
            // Beckmann
            const double Db = std::exp(-t2h / (a * a)) / (pi * a * a * std::pow(ch, 4));
            const auto lam_b = [&](const glm::dvec3& w) {
                const double x = 1 / (a * std::sqrt(tan2(w)));
                return (std::erf(x) - 1) / 2 + std::exp(-x * x) / (2 * x * std::sqrt(pi));
            };
            const double G2b = 1 / (1 + lam_b(V) + lam_b(L));
            CHECK(rel(K::ndf(h, a), Db) < 1e-10);
            CHECK(std::abs(K::lambda(V, a) - lam_b(V)) < 1e-12);  // tiny for large 1 / (alpha tan)
            CHECK(rel(K::g2(V, L, a), G2b) < 1e-10);
            CHECK(rel(K::eval(V, L, a), Db * G2b / (4 * V.z)) < 1e-10);
            CHECK(rel(K::pdf(V, L, a), Db * ch / (4 * std::abs(glm::dot(V, h)))) < 1e-10);
        }
    }
    // Closed-form spot values: GGX Lambda at tan theta = sqrt(3), alpha = 1 is (-1 + 2) / 2.
    CHECK(G::lambda(ltc::brdf::view_from_cos(0.5), 1.0) == Approx(0.5).epsilon(1e-14));
    CHECK(G::ndf(glm::dvec3(0, 0, 1), 0.5) == Approx(1 / (pi * 0.25)).epsilon(1e-14));
    CHECK(K::ndf(glm::dvec3(0, 0, 1), 0.5) == Approx(1 / (pi * 0.25)).epsilon(1e-14));
    CHECK(K::lambda(glm::dvec3(0, 0, 1), 0.5) == 0);
}

// (h) degenerate input: finite, non-negative results, and the documented limits.
TEMPLATE_TEST_CASE("brdf: degenerate input", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using T = typename B::scalar;
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;
    const T big = std::numeric_limits<T>::max(), below_one = T(1) - std::numeric_limits<T>::epsilon() / 2;
    const T tiny = std::numeric_limits<T>::min(), denorm = std::numeric_limits<T>::denorm_min();
    const std::vector<T> alphas_bad = {T(0), -T(1), denorm, tiny, T(1e-30), B::alpha_min, T(0.5), T(1), T(1e3),
                                       T(1e30), big};
    const std::vector<vec3> views = {
        vec3(0, 0, 1),
        vec3(1, 0, 0),                                   // V.z = 0
        vec3(0.6, 0, -0.8),                              // below the horizon
        ltc::brdf::view_from_cos<T>(T(1e-3)),            // grazing
        ltc::brdf::view_from_cos<T>(tiny),               // V.z = smallest normal
        vec3(1, 0, denorm),                              // V.z subnormal
        ltc::brdf::view_from_cos<T>(T(1) - std::numeric_limits<T>::epsilon()),  // nearly normal
    };
    const std::vector<vec2> us = {vec2(0, 0), vec2(0, below_one), vec2(below_one, 0), vec2(below_one, below_one),
                                  vec2(T(0.5), T(0.5)), vec2(1, 1)};
    for (const T a : alphas_bad)
        for (const vec3& V : views) {
            std::vector<vec3> lights = {-V, V, vec3(1, 0, 0), vec3(0, 0, 1), vec3(0, 0, -1), vec3(-V.x, -V.y, V.z),
                                        vec3(0, 1, 0), vec3(-1, 0, denorm)};
            for (const vec2& u : us) lights.push_back(B::sample(V, u, a));
            for (const vec2& u : us) {
                const vec3 L = B::sample(V, u, a);
                INFO(B::name << " alpha " << a << " V " << V.x << " " << V.y << " " << V.z << " u " << u.x << " "
                             << u.y);
                CHECK(finite(L));
                CHECK(std::abs(glm::length(L) - T(1)) <= 8 * std::numeric_limits<T>::epsilon());
            }
            for (const vec3& L : lights) {
                INFO(B::name << " alpha " << a << " V " << V.x << " " << V.y << " " << V.z << " L " << L.x << " "
                             << L.y << " " << L.z);
                const T values[] = {B::eval(V, L, a), B::pdf(V, L, a), B::ndf(L, a), B::lambda(L, a),
                                    B::g1(L, a), B::g2(V, L, a)};
                for (const T x : values) {
                    CHECK(std::isfinite(x));
                    CHECK(x >= T(0));
                }
                if (!(V.z > T(0)) || !(L.z > T(0))) CHECK(B::eval(V, L, a) == T(0));
                if (!(V.z > T(0))) CHECK(B::pdf(V, L, a) == T(0));
            }
            CHECK(B::eval(V, -V, a) == T(0));
            CHECK(B::pdf(V, -V, a) == T(0));
        }
    // alpha below the documented minimum behaves as the minimum (a Dirac is not a density).
    const vec3 V = ltc::brdf::view_from_cos<T>(T(0.7));
    const vec3 L(-V.x, -V.y, V.z);
    CHECK(B::eval(V, L, T(0)) == B::eval(V, L, B::alpha_min));
    CHECK(B::pdf(V, L, T(0)) == B::pdf(V, L, B::alpha_min));
    CHECK(B::eval(V, L, B::alpha_min) > T(0));
}

}  // namespace ltc_test_brdf_eval
