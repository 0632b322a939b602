// The fuzz harness's batches (tests/fuzz/fuzz_batch.hpp, for tests/fuzz/fuzz_shading.cpp): the
// instruction sets, and items made from the fuzzed bytes, in structures of arrays that
// AddressSanitizer watches.
#pragma once

#include "fuzz_common.hpp"

#include <ltc/ltc.hpp>
#include <ltc/reference/splitmix64.hpp>
#include <ltc/shading/batch.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace ltc_fuzz {

// Every instruction set this build and CPU run (isa::scalar always).
std::vector<ltc::batch::isa> batch_isas() {
    std::vector<ltc::batch::isa> v;
    for (const auto i : ltc::batch::instruction_sets)
        if (ltc::batch::available(i)) v.push_back(i);
    return v;
}

// How many leading items `which` may give to its SIMD kernel: whole vectors; the rest (the tail)
// always goes through the scalar path.
template <typename T>
std::size_t kernel_items(ltc::batch::isa which, std::size_t count) {
    const std::size_t w = ltc::batch::lane_count<T>(which);
    return w > 1 ? count - count % w : 0;
}

// count items of nv vertices; owns its structure-of-arrays copies, one heap array per vertex and
// axis, each exactly count long, so that AddressSanitizer sees any read past the last item.
template <typename T>
struct batch_items {
    using vec3 = glm::vec<3, T>;
    using mat3 = glm::mat<3, 3, T>;
    std::size_t nv = 0, count = 0;
    bool shared = false;              // one matrix (m_inv[0]) for every item
    std::vector<mat3> m_inv;          // per item
    std::vector<std::vector<vec3>> p;  // per item, nv vertices
    std::vector<std::vector<T>> x, y, z;
    std::vector<T> entry[3][3];
    std::vector<const T*> px, py, pz;

    void build_soa() {
        x.assign(nv, std::vector<T>(count)), y.assign(nv, std::vector<T>(count)), z.assign(nv, std::vector<T>(count));
        for (std::size_t i = 0; i < count; ++i)
            for (std::size_t k = 0; k < nv; ++k) x[k][i] = p[i][k].x, y[k][i] = p[i][k].y, z[k][i] = p[i][k].z;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) {
                entry[c][r].resize(count);
                for (std::size_t i = 0; i < count; ++i) entry[c][r][i] = m_inv[i][c][r];
            }
        px.clear(), py.clear(), pz.clear();
        for (std::size_t k = 0; k < nv; ++k) px.push_back(x[k].data()), py.push_back(y[k].data()), pz.push_back(z[k].data());
    }
    ltc::batch::matrices<T> matrices() const {
        if (shared) return ltc::batch::matrices<T>::same_for_all(m_inv[0]);
        const T* e[3][3];
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) e[c][r] = entry[c][r].data();
        return ltc::batch::matrices<T>::per_item(e);
    }
};

// M^-1 as the batch receives it: where the checked factory accepts the fuzzed matrix (finite, not
// numerically singular), the matrix it keeps (rescaled to a largest entry of 1) times +-2^e,
// |e| <= 20; the identity where it is rejected. Not the fuzzed matrix itself: from_inverse (and so
// the batch) does not rescale, and with entries near the largest finite value M^-1 p overflows
// even for a rescaled p, so that the scalar path itself returns NaN (found by this harness).
template <typename T>
glm::mat<3, 3, T> accepted_inverse(FuzzedDataProvider& in, const glm::mat<3, 3, T>& m) {
    const int e = in.ConsumeIntegralInRange<int>(-20, 20);
    const T sign = in.ConsumeBool() ? T(-1) : T(1);
    try {
        return ltc::transformed<ltc::clamped_cosine<T>>::checked_from_inverse(m).inverse_matrix() *
               (sign * std::ldexp(T(1), e));
    } catch (const ltc::invalid_transform&) {
        return glm::mat<3, 3, T>(T(1));
    }
}

// What tests/support/clip_comparison.hpp draws, in T: a GGX-fit-like M^-1 = [a 0 b; 0 c 0; d 0 1]
// or a general one with |det| > 0.05; a planar convex or star-shaped polygon, either winding,
// around a centre in front of or around the shading point.
template <typename T>
glm::mat<3, 3, T> random_matrix(ltc::ground_truth::splitmix64& g) {
    const auto u = [&](double lo, double hi) { return lo + (hi - lo) * g.uniform(); };
    if (g.uniform() < 0.5) {
        const double a = u(0.05, 1.05), b = u(-0.5, 0.5), c = u(0.05, 1.05), d = u(-0.5, 0.5);
        return glm::mat<3, 3, T>(glm::transpose(glm::dmat3(a, 0, b, 0, c, 0, d, 0, 1)));
    }
    for (;;) {
        glm::dmat3 m;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m[c][r] = u(-1, 1);
        if (std::abs(glm::determinant(m)) > 0.05) return glm::mat<3, 3, T>(m);
    }
}

template <typename T>
std::vector<glm::vec<3, T>> random_polygon(ltc::ground_truth::splitmix64& g, std::size_t n) {
    const auto u = [&](double lo, double hi) { return lo + (hi - lo) * g.uniform(); };
    const double pi = 3.141592653589793;
    // One draw per declarator (sequenced), never several in one constructor call (unspecified order).
    const double cx = u(-1, 1), cy = u(-1, 1), cc = u(-0.6, 1.0);
    const glm::dvec3 centre(cx, cy, cc);
    const double cz = u(-1, 1), phi = u(0, 2 * pi), sz = std::sqrt(1 - cz * cz);
    const glm::dvec3 normal(sz * std::cos(phi), sz * std::sin(phi), cz);
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 ex = glm::normalize(glm::cross(normal, helper)), ey = glm::cross(normal, ex);
    const double size = u(0.2, 1.5), phase = u(0, 2 * pi);
    const bool convex = g.uniform() < 0.5, reverse = g.uniform() < 0.5;
    std::vector<glm::vec<3, T>> v(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = phase + 2 * pi * static_cast<double>(k) / static_cast<double>(n);
        const double r = size * (convex ? u(0.8, 1.0) : (k % 2 ? u(0.15, 0.4) : 1.0));
        v[k] = glm::vec<3, T>(centre + r * (std::cos(t) * ex + std::sin(t) * ey));
    }
    if (reverse) std::reverse(v.begin(), v.end());
    return v;
}

// One item: a random well-conditioned one (the default, so that short inputs still fill the
// vector body), fuzzed values, the harness's own polygon and matrix, or a random one with one
// fuzzed defect (the degenerate cases of tests/test_batch.cpp, and scaled vertices).
template <typename T>
void make_item(FuzzedDataProvider& in, ltc::ground_truth::splitmix64& g, const glm::mat<3, 3, T>& m,
               const std::vector<glm::vec<3, T>>& v, std::size_t nv, glm::mat<3, 3, T>& mi,
               std::vector<glm::vec<3, T>>& p) {
    using vec3 = glm::vec<3, T>;
    const int mode = in.ConsumeIntegralInRange<int>(0, 3);
    mi = random_matrix<T>(g);
    p = random_polygon<T>(g, nv);
    if (mode == 1) {  // fuzzed
        if (in.ConsumeBool()) {
            glm::mat<3, 3, T> f;
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r) f[c][r] = finite_value<T>(in);
            mi = accepted_inverse(in, f);
        }
        for (auto& q : p) q = vec3(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    } else if (mode == 2) {  // the harness's polygon (repeated cyclically) and matrix
        mi = accepted_inverse(in, m);
        for (std::size_t k = 0; k < nv; ++k) p[k] = v.empty() ? vec3(T(0)) : v[k % v.size()];
    } else if (mode == 3) {  // one defect
        const std::size_t k = in.ConsumeIntegralInRange<std::size_t>(0, nv - 1), prev = (k + nv - 1) % nv;
        const auto scaled = [](vec3 q, int e) {
            const vec3 r(std::ldexp(q.x, e), std::ldexp(q.y, e), std::ldexp(q.z, e));
            return std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.z) ? r : q;
        };
        constexpr int emax = std::numeric_limits<T>::max_exponent, emin = std::numeric_limits<T>::min_exponent;
        switch (in.ConsumeIntegralInRange<int>(0, 8)) {
            case 0: p[k] = vec3(T(0)); break;  // a vertex at the origin
            case 1: p[k].z = T(0); break;      // a vertex on the plane z = 0
            case 2: p[k] = -p[prev]; break;    // an edge through the origin
            case 3: p[k] = p[prev]; break;     // a repeated vertex
            // The same direction at another length (the integral does not change).
            case 4: p[k] = scaled(p[k], in.ConsumeIntegralInRange<int>(-40, 40)); break;
            case 5: {  // the whole polygon scaled, into subnormals or near overflow
                const int e = in.ConsumeIntegralInRange<int>(emin - 30, emax);
                for (auto& q : p) q = scaled(q, e);
                break;
            }
            case 6: p[k] = vec3(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in)); break;
            case 7: for (auto& q : p) q.z = T(0); break;  // the polygon in the plane z = 0 (seen edge-on)
            default: p[k].z = finite_value<T>(in); break;  // z of one vertex fuzzed (near the horizon)
        }
    }
}

template <typename T>
batch_items<T> make_items(FuzzedDataProvider& in, const glm::mat<3, 3, T>& m, const std::vector<glm::vec<3, T>>& v,
                          std::size_t nv) {
    batch_items<T> it;
    it.nv = nv;
    // 1..19; 17 (two whole AVX2 float vectors and a tail of 1) for input that has run out.
    it.count = 1 + (in.ConsumeIntegral<std::uint8_t>() + 16u) % 19u;
    it.shared = in.ConsumeBool();
    ltc::ground_truth::splitmix64 g(in.ConsumeIntegral<std::uint64_t>());
    it.m_inv.resize(it.count), it.p.resize(it.count);
    for (std::size_t i = 0; i < it.count; ++i) make_item<T>(in, g, m, v, nv, it.m_inv[i], it.p[i]);
    if (it.shared)
        for (auto& mi : it.m_inv) mi = it.m_inv[0];
    it.build_soa();
    return it;
}

}  // namespace ltc_fuzz
