// Tests of ltc/shading/textured_light.hpp (sections 5.2 and 5.4: I_D I_L, the fetch parameterization, the
// world-space textured quad light). Its Monte Carlo reference, ltc/reference/textured_ground_truth.hpp,
// is tested in test_textured_ground_truth.cpp.
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/textured_light.hpp>

#include "support/images.hpp"
#include "support/rng.hpp"
#include "support/textured_quads.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace ltc_test_textured {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::textured_checks;  // ggx_lobe, random_quad, finite

namespace {

std::vector<glm::vec3> random_image(int w, int h, std::uint64_t seed) {
    return ltc_test::random_image(w, h, seed, 2);
}

template <typename T>
std::vector<glm::vec<3, T>> to(const std::vector<glm::vec3>& v) {
    return std::vector<glm::vec<3, T>>(v.begin(), v.end());
}

}  // namespace

TEST_CASE("fetch parameters: hand-computed cases", "[textured]") {
    // All values below are exact in binary or computed with one rounding; the fetch runs in
    // double, so 1e-12 relative covers it.
    SECTION("clamped cosine (M = I), quad in the plane z = 2") {
        const dvec3 q[4] = {{-1, -0.5, 2}, {3, -0.5, 2}, {3, 1.5, 2}, {-1, 1.5, 2}};
        const auto f = ltc::fetch_parameters(glm::dmat3(1.0), q);
        REQUIRE(f.valid);
        // Foot (0, 0, 2): u = 1/4, v = 0.5/2; A = 8, r = 2: sigma = 2 / sqrt(16).
        CHECK(f.uv.x == Approx(0.25).epsilon(1e-12));
        CHECK(f.uv.y == Approx(0.25).epsilon(1e-12));
        CHECK(f.sigma == Approx(0.5).epsilon(1e-12));
        CHECK(f.distance == Approx(2 / std::sqrt(8.0)).epsilon(1e-12));
        // The plane behind the shading point: same uv, same sigma (|r|).
        const dvec3 b[4] = {{-1, -0.5, -2}, {3, -0.5, -2}, {3, 1.5, -2}, {-1, 1.5, -2}};
        const auto g = ltc::fetch_parameters(glm::dmat3(1.0), b);
        CHECK(g.uv.x == Approx(0.25).epsilon(1e-12));
        CHECK(g.sigma == Approx(0.5).epsilon(1e-12));
    }
    SECTION("M^-1 = diag(2, 1, 1): uv unchanged (affine), the area doubles") {
        const dvec3 q[4] = {{-1, -0.5, 2}, {3, -0.5, 2}, {3, 1.5, 2}, {-1, 1.5, 2}};
        const auto f = ltc::fetch_parameters(glm::dmat3(2, 0, 0, 0, 1, 0, 0, 0, 1), q);
        CHECK(f.uv.x == Approx(0.25).epsilon(1e-12));
        CHECK(f.uv.y == Approx(0.25).epsilon(1e-12));
        CHECK(f.sigma == Approx(2 / std::sqrt(32.0)).epsilon(1e-12));
    }
    SECTION("shear M^-1 = [1 0 0.5; 0 1 0; 0 0 1]: the quad moves by +1 in x, the foot does not") {
        glm::dmat3 m(1.0);
        m[2][0] = 0.5;  // column 2, row 0: x' = x + 0.5 z
        const dvec3 q[4] = {{-1, -0.5, 2}, {3, -0.5, 2}, {3, 1.5, 2}, {-1, 1.5, 2}};
        const auto f = ltc::fetch_parameters(m, q);
        // q' spans x in [0, 4] at z = 2: foot (0, 0, 2) -> u = 0, v = 0.25; A = 8.
        CHECK(f.uv.x == Approx(0.0).margin(1e-12));
        CHECK(f.uv.y == Approx(0.25).epsilon(1e-12));
        CHECK(f.sigma == Approx(0.5).epsilon(1e-12));
    }
    SECTION("vertical light beside the shading point") {
        const dvec3 q[4] = {{2, -1, 0}, {2, 1, 0}, {2, 1, 2}, {2, -1, 2}};
        const auto f = ltc::fetch_parameters(glm::dmat3(1.0), q);
        // Foot (2, 0, 0): u = 0.5, v = 0 (the bottom edge); A = 4, |r| = 2: sigma = 2 / sqrt(8).
        CHECK(f.uv.x == Approx(0.5).epsilon(1e-12));
        CHECK(f.uv.y == Approx(0.0).margin(1e-12));
        CHECK(f.sigma == Approx(2 / std::sqrt(8.0)).epsilon(1e-12));
    }
    SECTION("foot far outside the texture") {
        const dvec3 q[4] = {{10, 0, 1}, {11, 0, 1}, {11, 1, 1}, {10, 1, 1}};
        const auto f = ltc::fetch_parameters(glm::dmat3(1.0), q);
        CHECK(f.uv.x == Approx(-10.0).epsilon(1e-12));
        CHECK(f.uv.y == Approx(0.0).margin(1e-12));
        CHECK(f.sigma == Approx(1 / std::sqrt(2.0)).epsilon(1e-12));
    }
    SECTION("scale invariance: the quad times 1e30 or 1e-30") {
        const dvec3 q[4] = {{-1, -0.5, 2}, {3, -0.5, 2}, {3, 1.5, 2}, {-1, 1.5, 2}};
        for (double s : {1e30, 1e-30, 1e300}) {
            dvec3 p[4];
            for (int i = 0; i < 4; ++i) p[i] = q[i] * s;
            const auto f = ltc::fetch_parameters(glm::dmat3(1.0), p);
            CHECK(f.uv.x == Approx(0.25).epsilon(1e-12));
            CHECK(f.sigma == Approx(0.5).epsilon(1e-12));
        }
    }
}

TEST_CASE("normalization: a constant texture gives exactly the untextured result", "[textured]") {
    const glm::vec3 c(0.75f, 2.5f, 0.125f);
    const std::vector<glm::vec3> img(std::size_t(8) * 5, c);
    const ltc::light_texture<float> tex(8, 5, img.data());
    ltc_test::rng r(11);
    for (int i = 0; i < 200; ++i) {
        dvec3 qd[4];
        random_quad(r, qd);
        glm::vec3 q[4];
        for (int k = 0; k < 4; ++k) q[k] = glm::vec3(qd[k]);
        const auto d = ggx_lobe(float(r.uniform(0, 1)), float(r.uniform(0, 1)));
        // lookup() returns c bit for bit (light_texture.hpp), so I_D I_L == I_D c exactly.
        const glm::vec3 textured = ltc::integrate_textured_quad(d, q, tex);
        CHECK(textured == d.integrate(q, 4) * c);
        for (auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided})
            CHECK(ltc::integrate_textured_quad(d, q, tex, side) == d.integrate(q, 4, side) * c);
    }
}

TEST_CASE("shade_textured_quad_light with a constant texture equals shade_polygon_light_one_lobe", "[textured]") {
    const glm::vec3 c(0.75f, 2.5f, 0.125f);
    const std::vector<glm::vec3> img(std::size_t(4) * 4, c);
    const ltc::light_texture<float> tex(4, 4, img.data());
    ltc_test::rng r(12);
    for (int i = 0; i < 200; ++i) {
        dvec3 qd[4];
        random_quad(r, qd);
        glm::vec3 q[4];
        const glm::vec3 P(float(r.uniform(-1, 1)), float(r.uniform(-1, 1)), float(r.uniform(-0.2, 0.2)));
        for (int k = 0; k < 4; ++k) q[k] = glm::vec3(qd[k]) + P;
        const glm::vec3 N = glm::normalize(glm::vec3(r.direction()) + glm::vec3(0, 0, 1.5f));
        const glm::vec3 V = glm::normalize(glm::vec3(r.direction()) + glm::vec3(0, 0, 1.2f));
        const float rough = float(r.uniform(0.05, 1));
        const glm::vec3 F0(0.04f, 0.5f, 1.0f), albedo(0.8f, 0.3f, 0.1f);
        for (auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided}) {
            const auto a = ltc::shade_textured_quad_light(P, N, V, rough, F0, albedo, q, tex, side);
            const auto b = ltc::shade_polygon_light_one_lobe(P, N, V, rough, F0, albedo, c, q, 4, side);
            // Same integrals (eq. 11 over M^-1 P) through two rounding paths (the polygon light
            // rescales the vertices first): each edge term is accurate to a few float ulps
            // (README, "Exactness"), 4 to 8 clipped edges, no cancellation beyond the largest
            // term, and the results are <= 2.5 (radiance) * 1 (albedo): 1e-5 absolute + 1e-5
            // relative is ~100 ulps of the largest term.
            for (int k = 0; k < 3; ++k) {
                CHECK(a.specular[k] == Approx(b.specular[k]).epsilon(1e-5).margin(1e-6));
                CHECK(a.diffuse[k] == Approx(b.diffuse[k]).epsilon(1e-5).margin(1e-6));
            }
        }
    }
}

TEST_CASE("symmetry: mirror about the plane of incidence; texture flipped with the corners relabelled",
          "[textured]") {
    const int w = 16, h = 12;
    const auto img = random_image(w, h, 13);
    std::vector<glm::vec3> flipped(img.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) flipped[std::size_t(y) * w + x] = img[std::size_t(y) * w + (w - 1 - x)];
    const ltc::light_texture<double> tex(w, h, to<double>(img).data()), tex_f(w, h, to<double>(flipped).data());
    ltc_test::rng r(14);
    for (int i = 0; i < 100; ++i) {
        dvec3 q[4];
        random_quad(r, q);
        const auto d = ggx_lobe(r.uniform(0, 1), r.uniform(0.05, 1));
        const dvec3 a = ltc::integrate_textured_quad(d, q, tex);
        // (1) Mirror y -> -y, each corner keeping its uv: the LTC of an isotropic BRDF is
        // symmetric about the plane of incidence (M^-1 has no x-y or y-z terms), so I_D, the
        // foot point's uv and sigma are unchanged up to double rounding (~1e-15 relative; the
        // lookup is Lipschitz in uv with constant <= 4 * (texels per unit) * 2 ~ 1e2), hence
        // 1e-10 relative.
        dvec3 m[4];
        for (int k = 0; k < 4; ++k) m[k] = dvec3(q[k].x, -q[k].y, q[k].z);
        const dvec3 b = ltc::integrate_textured_quad(d, m, tex);
        for (int k = 0; k < 3; ++k) CHECK(b[k] == Approx(a[k]).epsilon(1e-10).margin(1e-12));
        // (2) The same radiance field described by the flipped texture on the relabelled quad
        // (corner order 1, 0, 3, 2: uv' = (1 - u, v)). The flipped levels are the mirrored
        // levels within 1e-6 absolute (test_light_texture.cpp), so the results agree within
        // I_D * 1e-6 (plus double rounding).
        const dvec3 r4[4] = {q[1], q[0], q[3], q[2]};
        const dvec3 c = ltc::integrate_textured_quad(d, r4, tex_f);
        const double i_d = d.integrate(q, 4);
        for (int k = 0; k < 3; ++k) CHECK(std::abs(c[k] - a[k]) <= 1e-6 * i_d + 1e-12);
    }
}

TEST_CASE("the lod grows with the distance to the light", "[textured]") {
    const std::vector<glm::vec3> img(std::size_t(64) * 64, glm::vec3(1));
    const ltc::light_texture<double> tex(64, 64, to<double>(img).data());
    ltc_test::rng r(15);
    for (int i = 0; i < 50; ++i) {
        dvec3 q[4];
        random_quad(r, q);
        dvec3 n = glm::normalize(glm::cross(q[1] - q[0], q[3] - q[0]));
        if (glm::dot(n, q[0]) < 0) n = -n;  // away from the shading point
        const auto d = ggx_lobe(r.uniform(0, 1), r.uniform(0.05, 1));
        // Translating the light away along its normal moves its plane away in the cosine
        // configuration too (a linear map keeps parallel planes parallel and the area fixed),
        // so sigma = |r| / sqrt(2 A) grows strictly and the lod does not decrease.
        double prev_sigma = -1, prev_lod = -1;
        for (double t = 0; t < 50; t = 1.5 * t + 0.1) {
            dvec3 p[4];
            for (int k = 0; k < 4; ++k) p[k] = q[k] + t * n;
            const auto f = ltc::fetch_parameters(d.inverse_matrix(), p);
            REQUIRE(f.valid);
            CHECK(f.sigma > prev_sigma);
            const double lod = tex.lod_for_sigma(f.sigma);
            CHECK(lod >= prev_lod);
            prev_sigma = f.sigma;
            prev_lod = lod;
        }
        CHECK(prev_lod > 0);
    }
}

TEST_CASE("textured shading is finite for degenerate and extreme configurations", "[textured]") {
    const auto img = random_image(8, 8, 16);
    const ltc::light_texture<float> tex(8, 8, img.data());
    const auto d = ggx_lobe(0.3f, 0.2f);
    const float big = 1e30f, tiny = 1e-30f;
    const glm::vec3 cases[][4] = {
        {{-1, -1, -2}, {1, -1, -2}, {1, 1, -2}, {-1, 1, -2}},                  // below the horizon
        {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},                      // in the shading plane
        {{-1, -1, 1e-7f}, {1, -1, 1e-7f}, {1, 1, 1e-7f}, {-1, 1, 1e-7f}},      // grazing
        {{1e4f, 0, 1}, {1e4f + 1, 0, 1}, {1e4f + 1, 1, 1}, {1e4f, 1, 1}},      // foot far outside
        {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}},                          // a point
        {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}, {3, 0, 1}},                          // collinear
        {{0, 0, 0}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},                          // vertex at the origin
        {{-big, -big, big}, {big, -big, big}, {big, big, big}, {-big, big, big}},
        {{-tiny, -tiny, tiny}, {tiny, -tiny, tiny}, {tiny, tiny, tiny}, {-tiny, tiny, tiny}},
        {{-1, -1, 1}, {1, -1, 1}, {1, 1, -1}, {-1, 1, -1}},                    // straddling
    };
    for (const auto& q : cases) {
        for (auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided}) {
            CHECK(finite(ltc::integrate_textured_quad(d, q, tex, side)));
            const auto s = ltc::shade_textured_quad_light(glm::vec3(0), glm::vec3(0, 0, 1), glm::vec3(0.3f, 0, 1),
                                                          0.3f, glm::vec3(0.04f), glm::vec3(0.5f), q, tex, side);
            CHECK(finite(s.specular));
            CHECK(finite(s.diffuse));
            // V = N exactly, and N = 0.
            const auto t = ltc::shade_textured_quad_light(glm::vec3(0), glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), 0.3f,
                                                          glm::vec3(0.04f), glm::vec3(0.5f), q, tex, side);
            CHECK(finite(t.specular + t.diffuse));
            const auto z = ltc::shade_textured_quad_light(glm::vec3(0), glm::vec3(0), glm::vec3(0, 0, 1), 0.3f,
                                                          glm::vec3(0.04f), glm::vec3(0.5f), q, tex, side);
            CHECK(z.specular == glm::vec3(0));
        }
        const auto f = ltc::fetch_parameters(d.inverse_matrix(), q);
        CHECK(std::isfinite(f.uv.x));
        CHECK(std::isfinite(f.uv.y));
        CHECK(!std::isnan(f.sigma));
    }
}

}  // namespace ltc_test_textured
