// The batch tests' items (tests/test_batch.cpp, tests/test_batch_scaling.cpp): random quads and
// n-gons in structures of arrays, the instruction sets to test, and the comparison of a batch's
// output with the scalar path within ltc_test::clip_tolerance (derived in tests/test_batch.cpp).
#pragma once

#include "clip_comparison.hpp"
#include "rng.hpp"

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/batch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ltc_test {


// count items of n vertices, SoA, float; owns its arrays.
struct items {
    std::size_t n = 0, count = 0;
    std::vector<float> m[3][3];
    std::vector<std::vector<float>> x, y, z;

    items(std::size_t n_, std::size_t count_) : n(n_), count(count_), x(n_), y(n_), z(n_) {
        for (auto& col : m)
            for (auto& e : col) e.resize(count_);
        for (std::size_t k = 0; k < n; ++k) x[k].resize(count), y[k].resize(count), z[k].resize(count);
    }
    void set(std::size_t i, const glm::mat3& mi, const std::vector<glm::vec3>& v) {
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m[c][r][i] = mi[c][r];
        for (std::size_t k = 0; k < n; ++k) x[k][i] = v[k].x, y[k][i] = v[k].y, z[k][i] = v[k].z;
    }
    glm::mat3 matrix(std::size_t i) const {
        glm::mat3 mi;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) mi[c][r] = m[c][r][i];
        return mi;
    }
    std::vector<glm::vec3> polygon(std::size_t i) const {
        std::vector<glm::vec3> v(n);
        for (std::size_t k = 0; k < n; ++k) v[k] = glm::vec3(x[k][i], y[k][i], z[k][i]);
        return v;
    }
    ltc::batch::matrices<float> per_item() const {
        const float* e[3][3];
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) e[c][r] = m[c][r].data();
        return ltc::batch::matrices<float>::per_item(e);
    }
    template <std::size_t N>
    ltc::batch::polygon_soa<float, N> soa(const ltc::batch::matrices<float>& mats) const {
        ltc::batch::polygon_soa<float, N> p;
        p.m_inv = mats;
        for (std::size_t k = 0; k < N; ++k) p.x[k] = x[k].data(), p.y[k] = y[k].data(), p.z[k] = z[k].data();
        return p;
    }
};

// Pointer tables for the runtime-n API (kept alive by the caller).
struct ngon_view {
    std::vector<const float*> x, y, z;
    ltc::batch::ngon_soa<float> soa;
    ngon_view(const items& it, const ltc::batch::matrices<float>& mats) {
        for (std::size_t k = 0; k < it.n; ++k)
            x.push_back(it.x[k].data()), y.push_back(it.y[k].data()), z.push_back(it.z[k].data());
        soa.m_inv = mats;
        soa.n = it.n;
        soa.x = x.data(), soa.y = y.data(), soa.z = z.data();
    }
};

// The instruction sets to test here: every one this build and CPU run.
inline std::vector<ltc::batch::isa> isas() {
    std::vector<ltc::batch::isa> v;
    for (const auto i : ltc::batch::instruction_sets)
        if (ltc::batch::available(i)) v.push_back(i);
    return v;
}

template <typename Policy>
float scalar_value(const glm::mat3& mi, const std::vector<glm::vec3>& v, ltc::sidedness s) {
    return ltc::transformed<ltc::clamped_cosine<float, Policy>>::from_inverse(mi).integrate(v.data(), v.size(), s);
}

struct comparison {
    std::size_t violations = 0, crossing = 0, nonfinite = 0;
    unsigned masks_seen = 0;  // quads: bit k set where some item has the clip mask k
    double worst_ratio = 0;  // max |batch - scalar| / tolerance, where it occurs, and the values there
    std::size_t worst = 0;
    double worst_batch = 0, worst_scalar = 0, worst_tol = 0;
};

template <typename Policy>
comparison compare(const items& it, const std::vector<float>& out, ltc::sidedness s, const glm::mat3* shared = nullptr) {
    comparison c;
    for (std::size_t i = 0; i < it.count; ++i) {
        const glm::mat3 mi = shared ? *shared : it.matrix(i);
        const auto v = it.polygon(i);
        const float ref = scalar_value<Policy>(mi, v, s);
        const double tol = ltc_test::clip_tolerance<Policy>(mi, v);
        const double err = std::abs(static_cast<double>(out[i]) - static_cast<double>(ref));
        if (!std::isfinite(out[i])) ++c.nonfinite;
        if (!(err <= tol)) ++c.violations;
        const double ratio = err == 0 ? 0 : err / tol;
        if (ratio > c.worst_ratio) c.worst_ratio = ratio, c.worst = i, c.worst_batch = out[i], c.worst_scalar = ref, c.worst_tol = tol;
        bool below = false, above = false;
        unsigned mask = 0;
        for (std::size_t k = 0; k < v.size(); ++k) {
            const float qz = (mi * v[k]).z;
            below = below || qz < 0, above = above || qz >= 0;
            mask |= (qz >= 0 ? 1u : 0u) << (k % 16);
        }
        if (v.size() == 4) c.masks_seen |= 1u << mask;
        c.crossing += below && above;
    }
    return c;
}

// A planar arrowhead quad (tip, wing, reflex vertex, wing) whose wings are below the horizon and
// tip and reflex vertex above (mask 0101; 1010 with `shift`): two runs above the horizon, which
// random_polygon's star-shaped quads never give. Random size, tilt and azimuth.
inline std::vector<glm::vec3> two_run_quad(ltc_test::rng& g, bool shift) {
    const double tilt = g.uniform(0.3, 1.3), phi = g.uniform(0, 2 * ltc_test::kPi), size = g.uniform(0.3, 1.5);
    const double uv[4][2] = {{0, 2}, {1, -1}, {0, 0}, {-1, -1}};  // horizon at v = -0.5
    const glm::dvec3 eu(std::cos(phi), std::sin(phi), 0);
    const glm::dvec3 ev(-std::sin(phi) * std::cos(tilt), std::cos(phi) * std::cos(tilt), std::sin(tilt));
    const glm::dvec3 o = g.uniform(0.5, 2) * glm::dvec3(-std::sin(phi), std::cos(phi), 0) + 0.5 * size * ev;
    std::vector<glm::vec3> v(4);
    for (std::size_t k = 0; k < 4; ++k) {
        const auto& p = uv[(k + shift) % 4];
        v[k] = glm::vec3(o + size * (p[0] * eu + p[1] * ev));
    }
    return v;
}

inline items random_items(std::size_t n, std::size_t count, std::uint64_t seed, bool convex, bool general_matrix) {
    ltc_test::rng g(seed);
    items it(n, count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::mat3 m = random_matrix(g, general_matrix);  // two statements: a fixed order of draws
        if (n == 4 && !convex && i % 8 == 0)
            it.set(i, glm::mat3(1.0f), two_run_quad(g, i % 16 == 0));
        else
            it.set(i, m, random_polygon(g, n, convex, i % 2 == 1));
    }
    return it;
}

#define CHECK_COMPARISON(c, count)                                   \
    do {                                                             \
        CAPTURE((c).worst_ratio, (c).worst, (c).crossing);           \
        CAPTURE((c).worst_batch, (c).worst_scalar, (c).worst_tol);   \
        CHECK((c).violations == 0);                                  \
        CHECK((c).nonfinite == 0);                                   \
        CHECK((c).crossing > (count) / 5); /* the clipper is exercised */ \
    } while (0)


}  // namespace ltc_test
