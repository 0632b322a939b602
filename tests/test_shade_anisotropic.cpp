// Tests of ltc::shade<ltc::ggx::anisotropic> (ltc/shading/ggx_anisotropic_model.hpp) and the
// tangent frame (make_tangent_frame, view_azimuth): the brushed floor a user shades, against
// Monte Carlo of the real anisotropic GGX, where the orientation of the lobe is what is tested
// (the table's fit error is measured by tools/anisotropic_error_report); the frame's conventions
// (invariance under rotations of the whole scene, the tangent projected onto N's plane, its
// length and degenerate tangents); the roughnesses' clamping; and batch::shade. Every light
// against Monte Carlo of the model's own lobes: test_shade.cpp; many lights over one point in
// SIMD lanes: test_batch_shade.cpp.
#include <catch2/catch.hpp>

#include <ltc/brdf/ggx_anisotropic.hpp>
#include <ltc/ltc.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/ggx_anisotropic_model.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace ltc_test_shade_anisotropic {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dvec3;

template <typename T>
bool same_bits(const ltc::shading_result<T>& a, const ltc::shading_result<T>& b) {
    return std::memcmp(&a.specular, &b.specular, sizeof a.specular) == 0 &&
           std::memcmp(&a.diffuse, &b.diffuse, sizeof a.diffuse) == 0;
}

// A floor at P with normal N, brushed along `brush` (any vector not along N), seen from V, under
// a square light facing the point from the direction (theta_l, phi_l) of the frame.
struct floor_scene {
    dvec3 P, N, brush;
    double theta_v, phi_v;          // the view in the frame (N, brush projected), degrees
    double roughness, roughness_b;  // along the brush, across it
    double theta_l, phi_l, distance, half_size;

    dvec3 t1() const { return glm::normalize(brush - N * glm::dot(brush, N) / glm::dot(N, N)); }
    dvec3 n() const { return glm::normalize(N); }
    dvec3 t2() const { return glm::cross(n(), t1()); }
    dvec3 world(const dvec3& local) const { return local.x * t1() + local.y * t2() + local.z * n(); }
    static dvec3 direction(double theta, double phi) {
        const double t = glm::radians(theta), p = glm::radians(phi);
        return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
    }
    dvec3 view_local() const { return direction(theta_v, phi_v); }
    // The light's corners in the frame.
    std::vector<dvec3> light() const {
        const dvec3 d = direction(theta_l, phi_l), c = distance * d;
        const dvec3 u = glm::normalize(glm::cross(dvec3(0, 0, 1), d)), w = glm::cross(d, u);
        std::vector<dvec3> q = {c - half_size * (u + w), c + half_size * (u - w), c + half_size * (u + w),
                                c - half_size * (u - w)};
        return q;
    }
};

// Monte Carlo of the integral of anisotropic GGX (times the cosine) over the quad, in the frame.
double truth(const dvec3& V, double alpha_x, double alpha_y, const std::vector<dvec3>& quad) {
    ltc::ground_truth::options opt;
    opt.samples = 1u << 16;
    opt.seed = 39;
    const auto e = ltc::ground_truth::integrate(ltc::brdf::ggx_anisotropic<double>{}, V,
                                                ltc::brdf::anisotropic_alpha<double>{alpha_x, alpha_y}, quad.data(),
                                                quad.size(), opt);
    REQUIRE(e.standard_error < 0.02 * e.mean);
    return e.mean;
}

}  // namespace

// The user's program: a brushed floor under a quad light. With F0 = 1 the specular term is
// L magnitude I_ltc, the LTC's estimate of L times the integral of rho cos over the light. What
// is tested is the lobe's orientation in the tangent frame: the shading must be closer (by a
// factor 2) to the real BRDF's integral than to those of the three likely convention errors,
//   - phi_v of the wrong sign (V mirrored across the plane (N, tangent)),
//   - the roughnesses swapped (the tangent turned by 90 degrees),
//   - a lobe symmetric about the plane of incidence (the isotropic frame): the light mirrored
//     across that plane,
// in scenes where those integrals differ from the right one by more than the 8^4 table's own
// error (which reaches tens of percent for lights beside strongly anisotropic lobes:
// docs/results/anisotropic_error.md), each with its own world placement of the frame.
TEST_CASE("shade<ggx::anisotropic>: a brushed floor lights up where the real anisotropic GGX does",
          "[shade][anisotropic]") {
    const double r1 = std::sqrt(1.0 / 7), r4 = std::sqrt(4.0 / 7), r2 = std::sqrt(2.0 / 7), r5 = std::sqrt(5.0 / 7);
    const std::vector<floor_scene> scenes = {
        {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 40, 30, r1, r4, 40, 170, 3, 0.6},
        {{0.5, -1, 2}, {0.2, 0.3, 1}, {1, 1, 0.4}, 60, 30, r2, r5, 60, 170, 3, 0.6},
        {{0, 0, 0}, {-0.3, 1, 0.2}, {0, 0.2, 1}, 40, 30, r5, r2, 40, 170, 3, 0.6},
        {{1, 2, 3}, {0.1, -0.1, -1}, {-1, 0.5, 0}, 60, 30, 0.3, 0.6, 60, 230, 3, 0.6},
    };
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const floor_scene& sc = scenes[k];
        const dvec3 V = sc.view_local();
        const double ax = sc.roughness * sc.roughness, ay = sc.roughness_b * sc.roughness_b;
        floor_scene across = sc;  // the light mirrored across the plane of incidence
        across.phi_l = 2 * (sc.phi_v + 180) - sc.phi_l;
        const double want = truth(V, ax, ay, sc.light());
        const double wrong[3] = {truth({V.x, -V.y, V.z}, ax, ay, sc.light()), truth(V, ay, ax, sc.light()),
                                 truth(V, ax, ay, across.light())};
        REQUIRE(want > 0);
        for (const bool in_float : {false, true}) {
            double got;
            const double L = 2.0;
            if (in_float) {
                using v3 = glm::vec3;
                std::vector<v3> quad;
                for (const dvec3& x : sc.light()) quad.push_back(v3(sc.P + sc.world(x)));
                ltc::surface<float> s{v3(sc.P), v3(sc.N), v3(sc.world(sc.view_local()) * 3.0), float(sc.roughness),
                                      v3(1), v3(0), v3(sc.brush), float(sc.roughness_b)};
                got = ltc::shade<ltc::ggx::anisotropic>(s, ltc::polygon_light<float>::two_sided(quad.data(), 4, v3(L)))
                          .specular.y;
            } else {
                std::vector<dvec3> quad;
                for (const dvec3& x : sc.light()) quad.push_back(sc.P + sc.world(x));
                ltc::surface<double> s{sc.P, sc.N, sc.world(sc.view_local()) * 3.0, sc.roughness, dvec3(1), dvec3(0),
                                       sc.brush, sc.roughness_b};
                got = ltc::shade<ltc::ggx::anisotropic>(s, ltc::polygon_light<double>::two_sided(quad.data(), 4, dvec3(L)))
                          .specular.y;
            }
            CAPTURE(k, in_float, got / L, want, wrong[0], wrong[1], wrong[2]);
            for (const double w : wrong) CHECK(std::abs(got / L - want) < 0.5 * std::abs(got / L - w));
        }
    }
}

// Rotating and moving the whole scene (N, V, tangent, light) changes nothing but rounding: the
// frame follows the tangent, not the world axes. Tolerance (double): the rotated inputs are
// within a few u = 2^-53 of exact; the result's relative sensitivity to them is bounded by the
// conditioning of the LTC's M^-1 (below 10^3 for alpha >= 0.04) times the few dozen operations
// of the frame, the fetch and the edge terms, and by the fetch's slope across one node (the
// interpolation weights move by the same relative amount): 2^-30 covers 10^3 x 10^2 x 4 u with
// a margin of 20.
TEST_CASE("shade<ggx::anisotropic>: rotating the whole scene changes only rounding", "[shade][anisotropic]") {
    const dvec3 P(0.1, -0.2, 0.05), N(0.2, 0.1, 1), V(0.7, -0.3, 0.5), tangent(0.3, 0.9, 0.1);
    const std::vector<dvec3> quad = {{-1, 0.5, 0.3}, {1, 0.5, 0.3}, {1.2, 1.5, 1.6}, {-0.8, 1.5, 1.6}};
    const ltc::surface<double> s{P, N, V, 0.3, dvec3(0.9, 0.6, 0.3), dvec3(0.5), tangent, 0.65};
    const auto base = ltc::shade<ltc::ggx::anisotropic>(s, ltc::polygon_light<double>::two_sided(quad.data(), 4, dvec3(2)));
    REQUIRE(base.specular.x > 0);
    const double tol = std::ldexp(1.0, -30);
    for (const double degrees : {17.0, 90.0, 200.0})
        for (const dvec3 axis : {dvec3(0, 0, 1), dvec3(1, 2, -0.5)}) {
            const glm::dmat3 R = [&] {
                const dvec3 a = glm::normalize(axis);
                const double c = std::cos(glm::radians(degrees)), sn = std::sin(glm::radians(degrees));
                glm::dmat3 m(c);
                m += (1 - c) * glm::outerProduct(a, a);
                m += sn * glm::dmat3(0, a.z, -a.y, -a.z, 0, a.x, a.y, -a.x, 0);
                return m;
            }();
            const dvec3 shift(3, -1, 0.5);
            std::vector<dvec3> moved;
            for (const dvec3& x : quad) moved.push_back(R * x + shift);
            const ltc::surface<double> r{R * P + shift, R * N, R * V, 0.3, dvec3(0.9, 0.6, 0.3), dvec3(0.5), R * tangent, 0.65};
            const auto got =
                ltc::shade<ltc::ggx::anisotropic>(r, ltc::polygon_light<double>::two_sided(moved.data(), 4, dvec3(2)));
            CAPTURE(degrees, axis.x, axis.y, axis.z);
            for (int c = 0; c < 3; ++c) {
                CHECK(std::abs(got.specular[c] - base.specular[c]) <= tol * base.specular[c]);
                CHECK(std::abs(got.diffuse[c] - base.diffuse[c]) <= tol * base.diffuse[c]);
            }
        }
}

TEMPLATE_TEST_CASE("make_tangent_frame: the tangent's projection, its length, and degenerate tangents",
                   "[shade][anisotropic][bad_input]", float, double) {
    using T = TestType;
    using v3 = glm::vec<3, T>;
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
    const v3 N(T(0.2), T(0.1), T(1)), V(T(0.7), T(-0.3), T(0.5)), t(T(0.3), T(0.9), T(0.1));
    const v3 quad[4] = {{-1, 0.5, 0.3}, {1, 0.5, 0.3}, {1.2, 1.5, 1.6}, {-0.8, 1.5, 1.6}};
    const auto light = ltc::polygon_light<T>::two_sided(quad, 4, v3(2));
    ltc::surface<T> s{v3(T(0.1), T(-0.2), T(0.05)), N, V, T(0.3), v3(T(0.9), T(0.6), T(0.3)), v3(T(0.5)), t, T(0.65)};
    const auto at = [&](const v3& tangent) {
        ltc::surface<T> u = s;
        u.tangent = tangent;
        return ltc::shade<ltc::ggx::anisotropic>(u, light);
    };
    const auto base = at(t);
    REQUIRE(base.specular.x > T(0));

    SECTION("a tangent's length does not matter: powers of two give the same bits, tiny and huge ones too") {
        for (const int e : {-100, -60, -1, 1, 40, 100}) {
            if (std::ldexp(T(1), e) == T(0) || std::isinf(std::ldexp(T(1), e))) continue;
            CAPTURE(e);
            CHECK(same_bits(at(t * std::ldexp(T(1), e)), base));
        }
    }
    SECTION("only the tangent's projection onto N's plane counts (to rounding)") {
        // t + k N projects to t's projection: the frame's vectors move by a few ulps (the
        // projection is formed cancellation-free), the result by as many ulps of the integrals
        // (sums of O(1) terms, at most 1) times the radiance 2.
        const T tol = 64 * std::numeric_limits<T>::epsilon() * T(2);
        for (const T k : {T(-3), T(0.5), T(10)}) {
            const auto r = at(t + k * N);
            for (int c = 0; c < 3; ++c) CHECK(std::abs(r.specular[c] - base.specular[c]) <= tol);
        }
    }
    SECTION("a zero, non-finite or normal-parallel tangent takes a fixed direction, finite results") {
        const auto fallback = at(v3(0));
        for (int c = 0; c < 3; ++c) {
            CHECK(std::isfinite(fallback.specular[c]));
            CHECK(fallback.specular[c] >= T(0));
        }
        // The form factor does not depend on the frame's rotation about N (to rounding: the
        // file's tolerance for the projection below).
        for (int c = 0; c < 3; ++c)
            CHECK(std::abs(fallback.diffuse[c] - base.diffuse[c]) <= 64 * std::numeric_limits<T>::epsilon() * T(2));
        for (const v3 w : {v3(nan, 0, 1), v3(inf, 0, 0), v3(0, -inf, 0), N, -N, N * std::ldexp(T(1), -80)})
            CHECK(same_bits(at(w), fallback));
        // The frame itself: T1 = orthonormal_tangent(N), orthonormal to rounding.
        const auto f = ltc::make_tangent_frame(N, V, v3(0));
        const v3 n = glm::normalize(N);
        const v3 o = ltc::orthonormal_tangent(n);
        const T eps = 4 * std::numeric_limits<T>::epsilon();
        CHECK(glm::length(f.t1 - o) <= eps);
        CHECK(glm::length(f.t2 - glm::cross(n, o)) <= eps);
    }
    SECTION("a tangent almost along N is still a direction of N's plane") {
        const v3 almost = N + v3(T(0), std::numeric_limits<T>::epsilon() * T(4), T(0));
        const auto f = ltc::make_tangent_frame(N, V, almost);
        CHECK(std::abs(glm::dot(f.t1, glm::normalize(N))) <= 4 * std::numeric_limits<T>::epsilon());
        CHECK(std::abs(glm::length(f.t1) - T(1)) <= 4 * std::numeric_limits<T>::epsilon());
        const auto r = at(almost);
        for (int c = 0; c < 3; ++c) CHECK(std::isfinite(r.specular[c]));
    }
    SECTION("both roughnesses are clamped to [0, 1], NaN read as 0; swapping them is turning the tangent") {
        const auto with = [&](T rx, T ry) {
            ltc::surface<T> u = s;
            u.roughness = rx, u.roughness_bitangent = ry;
            return ltc::shade<ltc::ggx::anisotropic>(u, light);
        };
        CHECK(same_bits(with(T(0.3), T(-2)), with(T(0.3), T(0))));
        CHECK(same_bits(with(T(0.3), nan), with(T(0.3), T(0))));
        CHECK(same_bits(with(T(0.3), inf), with(T(0.3), T(1))));
        CHECK(same_bits(with(nan, T(0.65)), with(T(0), T(0.65))));
        CHECK(same_bits(with(T(5), T(0.65)), with(T(1), T(0.65))));
        for (const T rx : {T(0), T(1)})
            for (const T ry : {T(0), T(1)})
                for (int c = 0; c < 3; ++c) CHECK(std::isfinite(with(rx, ry).specular[c]));
    }
    SECTION("phi_v: V's azimuth from T1 towards T2") {
        const auto f = ltc::make_tangent_frame(v3(0, 0, 1), v3(1, 1, 1), v3(1, 0, 0));
        CHECK(std::abs(ltc::view_azimuth(f, v3(1, 1, 1)) - T(0.785398163397448)) <= 4 * std::numeric_limits<T>::epsilon());
        CHECK(std::abs(ltc::view_azimuth(f, v3(1, -1, 1)) + T(0.785398163397448)) <= 4 * std::numeric_limits<T>::epsilon());
        CHECK(ltc::view_azimuth(f, v3(0, 0, 1)) == T(0));
    }
}

// batch::shade of the anisotropic model over many points (no SIMD kernel: ltc::shade point by
// point, the same bits), with per-point tangents and roughnesses.
TEST_CASE("batch::shade<ggx::anisotropic>: per-point tangents, ltc::shade's bits", "[shade][anisotropic][batch]") {
    const std::size_t count = 37;
    std::vector<float> f[20];
    for (std::size_t i = 0; i < count; ++i) {
        const float a = float(i) * 0.37f;
        const float v[20] = {std::sin(a), std::cos(a), 0.1f, 0.1f * std::cos(3 * a), 0.2f, 1, std::cos(a), 0.4f, 0.8f,
                             0.1f + 0.02f * float(i), 0.9f, 0.6f, 0.3f, 0.5f, 0.5f, 0.5f,
                             std::cos(2 * a), std::sin(2 * a), 0.3f, 0.9f - 0.02f * float(i)};
        for (int k = 0; k < 20; ++k) f[k].push_back(v[k]);
    }
    f[16][5] = f[17][5] = f[18][5] = 0;  // a zero tangent
    ltc::batch::surfaces<float> pts{count, {f[0].data(), f[1].data(), f[2].data()}, {f[3].data(), f[4].data(), f[5].data()},
                                    {f[6].data(), f[7].data(), f[8].data()}, f[9].data(),
                                    {f[10].data(), f[11].data(), f[12].data()}, {f[13].data(), f[14].data(), f[15].data()},
                                    {f[16].data(), f[17].data(), f[18].data()}, f[19].data()};
    const glm::vec3 quad[4] = {{-1, 0.5f, 1.3f}, {1, 0.5f, 1.3f}, {1.2f, 1.5f, 1.6f}, {-0.8f, 1.5f, 1.6f}};
    const auto light = ltc::polygon_light<float>::one_sided(quad, 4, glm::vec3(0, 0, -1), glm::vec3(2));
    std::vector<float> out[6];
    for (auto& o : out) o.assign(count, -1.0f);
    ltc::batch::shading_results<float> r;
    for (int c = 0; c < 3; ++c) r.specular[c] = out[c].data(), r.diffuse[c] = out[3 + c].data();
    ltc::batch::shade<ltc::ggx::anisotropic>(pts, light, r);
    std::size_t differ = 0, lit = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const auto want = ltc::shade<ltc::ggx::anisotropic>(pts.at(i), light);
        const ltc::shading_result<float> got{{out[0][i], out[1][i], out[2][i]}, {out[3][i], out[4][i], out[5][i]}};
        differ += !same_bits(got, want);
        lit += want.specular.x > 0;
        // The tangent is the point's own: shading with another gives another answer.
        if (i == 3) {
            ltc::surface<float> turned = pts.at(i);
            turned.tangent = glm::cross(turned.normal, turned.tangent);
            CHECK(ltc::shade<ltc::ggx::anisotropic>(turned, light).specular.x != want.specular.x);
        }
    }
    CHECK(differ == 0);
    CHECK(lit > count / 2);
}

}  // namespace ltc_test_shade_anisotropic
