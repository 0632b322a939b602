// Tests of ltc/shading/light_texture.hpp: the prefiltered levels of section 5.3 against a direct
// (non-separable, untruncated) evaluation of their definition, normalization, symmetry, the
// lod mapping and robustness.
#include <ltc/shading/light_texture.hpp>

#include "support/rng.hpp"
#include "support/images.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

namespace ltc_test_light_texture {  // the file's own names, apart from the other files of a unity batch

namespace {

std::vector<glm::vec3> random_image(int w, int h, std::uint64_t seed) {
    return ltc_test::random_image(w, h, seed, 0.01);
}

/// The definition (*) of light_texture.hpp evaluated directly in 2D, in double, over every
/// texel (no separation, no truncation).
glm::dvec3 brute_force(const std::vector<glm::vec3>& img, int w, int h, double sigma, double px, double py) {
    const double dx = std::max(0.0, std::max(-px, px - 1)), dy = std::max(0.0, std::max(-py, py - 1));
    const double sx2 = sigma * sigma + dx * dx, sy2 = sigma * sigma + dy * dy;
    glm::dvec3 num(0.0);
    double den = 0;
    // sigma = 0 inside the texture: the limit of (*) is the nearest texel.
    if (sx2 == 0 || sy2 == 0) {
        int x = std::min(std::max(int(std::floor(px * w)), 0), w - 1);
        int y = std::min(std::max(int(std::floor(py * h)), 0), h - 1);
        if (sx2 == 0 && sy2 == 0) return glm::dvec3(img[std::size_t(y) * w + x]);
        // one axis degenerate: 1D Gaussian along the other
        for (int t = 0; t < (sx2 == 0 ? h : w); ++t) {
            const double c = (t + 0.5) / (sx2 == 0 ? h : w);
            const double p = sx2 == 0 ? py : px;
            const double s2 = sx2 == 0 ? sy2 : sx2;
            const double wt = std::exp(-(p - c) * (p - c) / (2 * s2));
            num += wt * glm::dvec3(sx2 == 0 ? img[std::size_t(t) * w + x] : img[std::size_t(y) * w + t]);
            den += wt;
        }
        return num / den;
    }
    // Relative to the largest weight so that nothing underflows.
    double best = std::numeric_limits<double>::infinity();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double cx = (x + 0.5) / w, cy = (y + 0.5) / h;
            best = std::min(best, (px - cx) * (px - cx) / (2 * sx2) + (py - cy) * (py - cy) / (2 * sy2));
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double cx = (x + 0.5) / w, cy = (y + 0.5) / h;
            const double e = (px - cx) * (px - cx) / (2 * sx2) + (py - cy) * (py - cy) / (2 * sy2);
            const double wt = std::exp(-(e - best));
            num += wt * glm::dvec3(img[std::size_t(y) * w + x]);
            den += wt;
        }
    return num / den;
}

void check_against_brute_force(int w, int h, double margin, std::uint64_t seed) {
    const auto img = random_image(w, h, seed);
    const ltc::light_texture<float> tex(w, h, img.data(), margin);
    double max_l = 0;
    for (const auto& c : img) max_l = std::max({max_l, double(c.x), double(c.y), double(c.z)});
    // Tolerance. The separable filter computes the same weighted average as brute_force, in
    // double (relative rounding ~ (taps) 2^-53 < 1e-12), minus the truncated tails (each tap
    // dropped is < exp(-24.5) = 2.3e-11 of the peak, their sum < 1e-10 of the total weight,
    // changing the average by < 1e-10 max|L|), then rounds once to float (<= 2^-24 |value|,
    // round to nearest). So |level - brute| <= 2^-24 |brute| + 1e-9 max|L| holds with margin.
    const double tol_abs = 1e-9 * max_l;
    int checked = 0;
    for (int k = 0; k < tex.level_count(); ++k) {
        const auto& L = tex.get_level(k);
        CHECK(L.sigma == tex.sigma_of_level(k));
        for (int j = 0; j < L.y.count(); ++j)
            for (int i = 0; i < L.x.count(); ++i) {
                const glm::dvec3 ref = brute_force(img, w, h, L.sigma, L.x.position(i), L.y.position(j));
                const glm::dvec3 got(L.at(i, j));
                for (int c = 0; c < 3; ++c) {
                    const double tol = std::ldexp(std::abs(ref[c]), -24) + tol_abs;
                    if (!(std::abs(got[c] - ref[c]) <= tol)) {
                        INFO("level " << k << " sample (" << i << ", " << j << ") channel " << c << ": " << got[c]
                                      << " vs " << ref[c]);
                        CHECK(std::abs(got[c] - ref[c]) <= tol);
                    }
                }
                ++checked;
            }
    }
    CHECK(checked > 0);
}

}  // namespace

TEST_CASE("light_texture levels match a direct evaluation of the clamped, renormalized Gaussian",
          "[light_texture]") {
    SECTION("small non-square image, wide margin (kernels cover the whole image)") {
        check_against_brute_force(12, 9, 0.25, 1);
    }
    SECTION("larger image, default margin (kernels truncated inside the image)") {
        check_against_brute_force(40, 33, ltc::light_texture<float>::default_margin, 2);
    }
    SECTION("one-texel-high image") { check_against_brute_force(17, 1, 0.25, 3); }
}

TEST_CASE("light_texture level layout", "[light_texture]") {
    const int w = 32, h = 16;
    const auto img = random_image(w, h, 4);
    const ltc::light_texture<float> tex(w, h, img.data(), 0.25);
    // sigma_0 = 0, sigma_k = 2^(k-1) / max(w, h), last level the first with sigma >= 2.
    CHECK(tex.sigma_of_level(0) == 0.0);
    for (int k = 1; k < tex.level_count(); ++k) CHECK(tex.sigma_of_level(k) == std::ldexp(1.0, k - 1) / 32);
    CHECK(tex.sigma_of_level(tex.level_count() - 1) >= 2.0);
    CHECK(tex.sigma_of_level(tex.level_count() - 2) < 2.0);
    for (int k = 0; k < tex.level_count(); ++k) {
        const auto& L = tex.get_level(k);
        // Margin: the level's samples reach at least [-margin, 1 + margin] (outermost cell edge).
        CHECK(L.x.position(0) - 0.5 / L.x.cells <= -0.25 + 1e-12);
        CHECK(L.y.position(L.y.count() - 1) + 0.5 / L.y.cells >= 1.25 - 1e-12);
        // Pitch: the texel pitch or at most sigma / 2 (never coarser than that unless 1 cell).
        if (k >= 1 && L.x.cells > 1) CHECK(1.0 / L.x.cells <= std::max(1.0 / w, tex.sigma_of_level(k) / 2) + 1e-12);
        if (k == 0) CHECK((L.x.cells == w && L.y.cells == h));
    }
    // Level 0 inside the texture is the image itself.
    const auto& L0 = tex.get_level(0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) CHECK(L0.at(x + L0.x.margin_cells, y + L0.y.margin_cells) == img[std::size_t(y) * w + x]);
    // Level 0 lookup at a texel centre returns the texel.
    CHECK(tex.lookup(glm::vec2((5 + 0.5f) / w, (7 + 0.5f) / h), 0.0f) == img[7 * w + 5]);
}

TEST_CASE("light_texture: a constant texture stays exactly constant", "[light_texture]") {
    const glm::vec3 c(0.75f, 2.5f, 1.0f / 3.0f);
    const std::vector<glm::vec3> img(std::size_t(13) * 7, c);
    const ltc::light_texture<double> tex(13, 7, std::vector<glm::dvec3>(img.begin(), img.end()).data());
    for (int k = 0; k < tex.level_count(); ++k)
        for (const auto& t : tex.get_level(k).texels) CHECK(t == c);
    ltc_test::rng r(5);
    for (int i = 0; i < 500; ++i) {
        const glm::dvec2 uv(r.uniform(-3, 4), r.uniform(-3, 4));
        const double lod = r.uniform(-1, tex.level_count() + 1);
        CHECK(tex.lookup(uv, lod) == glm::dvec3(c));
    }
}

TEST_CASE("light_texture: mirrored image gives mirrored levels", "[light_texture]") {
    const int w = 11, h = 6;
    const auto img = random_image(w, h, 6);
    std::vector<glm::vec3> flipped(img.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) flipped[std::size_t(y) * w + x] = img[std::size_t(y) * w + (w - 1 - x)];
    const ltc::light_texture<float> a(w, h, img.data(), 0.25), b(w, h, flipped.data(), 0.25);
    REQUIRE(a.level_count() == b.level_count());
    // Both are within 2^-24 |value| + 1e-9 max|L| of their exact (mirror-symmetric) definition
    // (previous test), so they differ by at most twice that: 2 (2^-24 4 + 4e-9) < 1e-6.
    for (int k = 0; k < a.level_count(); ++k) {
        const auto& A = a.get_level(k);
        const auto& B = b.get_level(k);
        for (int j = 0; j < A.y.count(); ++j)
            for (int i = 0; i < A.x.count(); ++i) {
                const glm::vec3 d = A.at(i, j) - B.at(A.x.count() - 1 - i, j);
                CHECK(std::abs(d.x) + std::abs(d.y) + std::abs(d.z) < 1e-6f);
            }
    }
}

TEST_CASE("light_texture: lod_for_sigma inverts sigma_k and is monotonic", "[light_texture]") {
    const int w = 64, h = 64;
    const std::vector<glm::vec3> img(std::size_t(w) * h, glm::vec3(1));
    const ltc::light_texture<float> tex(w, h, img.data());
    for (int k = 0; k < tex.level_count(); ++k)
        CHECK(tex.lod_for_sigma(float(tex.sigma_of_level(k))) == Approx(k).margin(1e-5));
    float prev = -1;
    for (float s = 0; s < 10; s = s * 1.1f + 1e-4f) {
        const float lod = tex.lod_for_sigma(s);
        CHECK(lod >= prev);
        prev = lod;
    }
    const float last = float(tex.level_count() - 1);
    CHECK(tex.lod_for_sigma(std::numeric_limits<float>::infinity()) == last);
    CHECK(tex.lod_for_sigma(std::numeric_limits<float>::quiet_NaN()) == last);
    CHECK(tex.lod_for_sigma(-1.0f) == 0.0f);
}

TEST_CASE("light_texture: trilinear lookup and finite results for any input", "[light_texture]") {
    const int w = 9, h = 5;
    const auto img = random_image(w, h, 7);
    const ltc::light_texture<float> tex(w, h, img.data(), 0.25);
    // At an integer lod, the lookup is that level's bilinear lookup; halfway, the average.
    const glm::vec2 uv(0.3f, 0.8f);
    CHECK(tex.lookup(uv, 2.0f) == tex.lookup_level(uv, 2));
    const glm::vec3 mid = tex.lookup(uv, 2.5f), expect = 0.5f * (tex.lookup_level(uv, 2) + tex.lookup_level(uv, 3));
    CHECK(glm::length(mid - expect) < 1e-6f);
    // Clamp beyond the margin: far points read the outermost samples.
    CHECK(tex.lookup(glm::vec2(-50.0f, 0.5f), 1.0f) == tex.lookup(glm::vec2(-5.0f, 0.5f), 1.0f));
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float bad[] = {inf, -inf, nan, 1e30f, -1e30f, 0.5f};
    for (float u : bad)
        for (float v : bad)
            for (float lod : bad) {
                const glm::vec3 c = tex.lookup(glm::vec2(u, v), lod);
                CHECK((std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)));
            }
}

TEST_CASE("light_texture rejects invalid input", "[light_texture]") {
    const std::vector<glm::vec3> img(4, glm::vec3(1));
    CHECK_THROWS_AS(ltc::light_texture<float>(0, 2, img.data()), std::invalid_argument);
    CHECK_THROWS_AS(ltc::light_texture<float>(2, 2, nullptr), std::invalid_argument);
    CHECK_THROWS_AS(ltc::light_texture<float>(2, 2, img.data(), -1.0), std::invalid_argument);
    std::vector<glm::vec3> bad = img;
    bad[2].y = std::numeric_limits<float>::infinity();
    CHECK_THROWS_AS(ltc::light_texture<float>(2, 2, bad.data()), std::invalid_argument);
}

}  // namespace ltc_test_light_texture
