// Screen-ordered sample points (ltc/core/screen_order.hpp) and the lattices shifted by them
// (shadow_options::stratified_rotation, ltc/shading/shadowed_polygon_light.hpp; the sums'
// expectations under it: tests/test_shadowed_polygon_light.cpp):
//   (a) every aligned 2^k x 2^k block of pixels holds a (0, 2k, 2)-net in base 2: one point in
//       each elementary interval of area 4^-k, of every shape (k = 1..4; exact integer checks);
//   (b) each pixel's point is uniform over the seeds (chi-square, 8 x 8 cells);
//   (c) the scrambling's parts: Morton codes interleave the bits; Owen's scrambling maps every
//       aligned dyadic interval onto one of the same length (the top m bits of the result depend
//       on the top m bits of the input only) and is a bijection;
//   (d) the per-period shifts of a block of pixels stratify their n-point lattices together, for
//       any n: the block's n 4^k first coordinates are one per interval of width 1 / (n 4^k); the
//       second coordinates are the unshifted lattice's plus the point's.
#include "support/chi_square.hpp"
#include "support/rng.hpp"

#include <ltc/core/screen_order.hpp>
#include <ltc/shading/shadowed_polygon_light.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

namespace ltc_test_screen_order {  // the file's own names, apart from the other files of a unity batch

namespace {

/// The point's binary digits: the top `bits` of each coordinate (exact: the coordinates are
/// multiples of 2^-24 in float, 2^-32 in double).
template <typename T>
std::uint32_t digits(T c, int bits) {
    return static_cast<std::uint32_t>(static_cast<double>(c) * double(1u << bits));
}

}  // namespace

TEMPLATE_TEST_CASE("screen order: aligned blocks of pixels hold (0, 2k, 2)-nets", "[screen_order]", float, double) {
    for (std::uint64_t seed : {0x0ull, 0x9e3779b97f4a7c15ull, 0x123456789abcdefull}) {
        for (int k = 1; k <= 4; ++k) {
            const int side = 1 << k;
            for (int bx = 0; bx < 3; ++bx)
                for (int by = 0; by < 3; ++by) {
                    // The block at (x0, y0) = (bx, by) 2^k, and one far away (the 16-bit wrap too).
                    for (std::uint32_t far : {0u, 40000u}) {
                        std::vector<glm::vec<2, TestType>> p;
                        for (int y = 0; y < side; ++y)
                            for (int x = 0; x < side; ++x)
                                p.push_back(ltc::screen_point<TestType>(far + std::uint32_t(bx * side + x),
                                                                        far + std::uint32_t(by * side + y), seed));
                        for (int i = 0; i <= 2 * k; ++i) {  // intervals 2^-i wide, 2^-(2k - i) high
                            std::set<std::uint64_t> cells;
                            for (const auto& q : p) {
                                CHECK(q.x >= TestType(0));
                                CHECK(q.x < TestType(1));
                                CHECK(q.y >= TestType(0));
                                CHECK(q.y < TestType(1));
                                cells.insert(std::uint64_t(digits(q.x, i)) << 32 | digits(q.y, 2 * k - i));
                            }
                            CAPTURE(seed, k, bx, by, far, i);
                            CHECK(cells.size() == p.size());
                        }
                    }
                }
        }
    }
}

TEST_CASE("screen order: each pixel's point is uniform over the seeds", "[screen_order]") {
    // 6400 seeds (SplitMix64 words), 64 cells: X^2 against the 1e-4 critical value.
    for (const auto& pixel : {std::pair<std::uint32_t, std::uint32_t>{0, 0}, {5, 3}, {1000, 77}}) {
        const long n = 6400;
        std::vector<long> counts(64, 0);
        ltc_test::rng seeds(0x243f6a8885a308d3ull);
        for (long i = 0; i < n; ++i) {
            const glm::vec2 p = ltc::screen_point<float>(pixel.first, pixel.second, seeds.next_u64());
            ++counts[std::size_t(digits(p.x, 3) * 8 + digits(p.y, 3))];
        }
        const ltc_test::chi_square r = ltc_test::chi_square_test(std::vector<double>(64, 1.0 / 64), counts, n);
        CAPTURE(pixel.first, pixel.second, r.x2, r.dof);
        CHECK(r.dof == 63);
        CHECK(r.x2 < r.critical);
    }
}

TEST_CASE("screen order: Morton codes and Owen's scrambling", "[screen_order]") {
    CHECK(ltc::detail::morton_code(0u, 0u) == 0u);
    CHECK(ltc::detail::morton_code(1u, 0u) == 1u);
    CHECK(ltc::detail::morton_code(0u, 1u) == 2u);
    CHECK(ltc::detail::morton_code(3u, 5u) == 0x27u);  // x = 011, y = 101: 10 01 11
    CHECK(ltc::detail::morton_code(0xffffu, 0u) == 0x55555555u);
    CHECK(ltc::detail::morton_code(0x10000u, 0x10000u) == 0u);  // 16 bits each
    CHECK(ltc::detail::reverse_bits(1u) == 0x80000000u);
    // Sobol's second dimension by its direction numbers v_{b+1} = v_b ^ (v_b >> 1), one per bit.
    for (std::uint32_t i : {0u, 1u, 2u, 3u, 5u, 0x80000000u, 0xffffffffu, 0x12345678u, 0xdeadbeefu}) {
        std::uint32_t second = 0, v = 1u << 31;
        for (std::uint32_t b = i; b != 0; b >>= 1, v ^= v >> 1)
            if (b & 1u) second ^= v;
        CAPTURE(i);
        CHECK(ltc::detail::reverse_bits(ltc::detail::sobol_second_reversed(i)) == second);
    }
    CHECK(ltc::detail::reverse_bits(0x12345678u) == 0x1e6a2c48u);
    // Nested: the top m bits of the scrambled value depend on the top m bits only.
    std::uint32_t x = 0x2545f491u;
    for (int trial = 0; trial < 200; ++trial) {
        x = x * 1664525u + 1013904223u;
        const std::uint32_t seed = x ^ 0xa5a5a5a5u;
        for (int m = 1; m <= 31; ++m) {
            const std::uint32_t low = (1u << (32 - m)) - 1u;  // the bits below the top m
            const std::uint32_t a = ltc::detail::owen_scramble(x, seed);
            const std::uint32_t b = ltc::detail::owen_scramble(x ^ (x * 2654435761u & low), seed);
            CHECK((a & ~low) == (b & ~low));
        }
    }
    // A bijection: all 2^16 values with the low 16 bits 0 map to distinct top halves.
    std::set<std::uint32_t> images;
    for (std::uint32_t v = 0; v < (1u << 16); ++v) images.insert(ltc::detail::owen_scramble(v << 16, 0x5bd1e995u) >> 16);
    CHECK(images.size() == (1u << 16));
}

TEST_CASE("screen order: per-period lattice shifts stratify a block's lattices together", "[screen_order]") {
    // shadow_options::stratified_rotation: a lattice of n points shifted by p.x / n along its first
    // coordinate, p a pixel's screen-ordered point. Over an aligned 2^k x 2^k block, for every n
    // (each technique's own count), the n 4^k first coordinates are one per interval of width
    // 1 / (n 4^k), binned from the points the library computes (float, rounded by about 2^-21:
    // a point could cross a cell's edge only if p.x lay that close to one, which these fixed
    // seeds' points do not); the second coordinates are k / phi + p.y mod 1, unchanged.
    const std::uint64_t seed = 0x0123456789abcdefull;
    for (std::size_t n : {1u, 3u, 4u, 7u, 8u}) {
        for (int k = 1; k <= 3; ++k) {
            const int side = 1 << k;
            const std::size_t cells = n * std::size_t(side * side);
            std::set<std::size_t> used;
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x) {
                    const glm::vec2 p = ltc::screen_point<float>(std::uint32_t(x + 8), std::uint32_t(y), seed);
                    for (std::size_t j = 0; j < n; ++j) {
                        const glm::vec2 u = ltc::detail::lattice_point(j, n, p, true);
                        const glm::vec2 plain = ltc::detail::lattice_point(j, n, glm::vec2(0.0f, p.y));
                        CHECK(u.y == plain.y);
                        CHECK(u.x >= 0.0f);
                        CHECK(u.x < 1.0f);
                        used.insert(std::size_t(double(u.x) * double(cells)));
                    }
                }
            CAPTURE(n, k);
            CHECK(used.size() == cells);
        }
    }
}

}  // namespace ltc_test_screen_order
