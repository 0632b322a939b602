// ltc/core/screen_order.hpp -- per-pixel sample points stratified across neighbouring pixels:
// a screen-space ordering of scrambled Sobol points (Ahmed and Wonka, "Screen-space blue-noise
// diffusion of Monte Carlo sampling error via hierarchical ordering of pixels", SIGGRAPH Asia
// 2020; the shuffle and scrambling of Burley, "Practical Hash-based Owen Scrambling", JCGT 2020).
//
//   glm::vec2 u = ltc::screen_point(x, y, image_seed);   // in [0, 1)^2
//
// Conventions: each pixel's point is uniform over [0, 1)^2 over the seeds; an aligned 2^k x 2^k
// block of pixels holds a (0, 2k, 2)-net (float: k <= 12), whose errors partly cancel in a filter
// over neighbouring pixels. Used as the shadowed shading's lattice rotation:
// shadow_options::stratified_rotation.
#pragma once

#include <ltc/config.hpp>

#include <glm/glm.hpp>

#include <cstdint>
#include <type_traits>

LTC_NAMESPACE_BEGIN

namespace detail {

LTC_HOST_DEVICE LTC_INLINE std::uint32_t reverse_bits(std::uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

/// A permutation of 32-bit integers in which each bit depends only on the bits below it, random
/// over the seeds (Laine and Karras 2011, with the multipliers of Burley 2020).
LTC_HOST_DEVICE LTC_INLINE std::uint32_t lower_bits_permutation(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

/// Owen's nested uniform scrambling of x's binary digits, the most significant first (Burley 2020:
/// the permutation above on the reversed bits).
LTC_HOST_DEVICE LTC_INLINE std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed) {
    return reverse_bits(lower_bits_permutation(reverse_bits(x), seed));
}

/// v's 16 low bits at the even places.
LTC_HOST_DEVICE LTC_INLINE std::uint32_t spread_bits(std::uint32_t v) {
    v &= 0xffffu;
    v = (v | (v << 8)) & 0x00ff00ffu;
    v = (v | (v << 4)) & 0x0f0f0f0fu;
    v = (v | (v << 2)) & 0x33333333u;
    return (v | (v << 1)) & 0x55555555u;
}

/// x's 16 low bits at the even places, y's at the odd ones.
LTC_HOST_DEVICE LTC_INLINE std::uint32_t morton_code(std::uint32_t x, std::uint32_t y) {
    return spread_bits(x) | (spread_bits(y) << 1);
}

/// A 32-bit binary fraction as T in [0, 1): float keeps the top 24 bits (rounding more could give 1).
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T unit_fraction(std::uint32_t d) {
    if constexpr (std::is_same<T, float>::value)
        return T(d >> 8) * T(1.0 / 16777216.0);
    else
        return T(d) * T(1.0 / 4294967296.0);
}

/// Sobol's second dimension at `index`, its binary digits reversed (bit j: the digit of 2^-(j+1)):
/// the product of the Pascal matrix mod 2 with the index's bits, C(j, i) mod 2, which is the
/// substitution t -> t + 1 in the polynomial sum_j bit_j t^j over GF(2); since (t + 1)^16 =
/// t^16 + 1 there, halves split recursively: log2(32) steps instead of a loop over the bits.
LTC_HOST_DEVICE LTC_INLINE std::uint32_t sobol_second_reversed(std::uint32_t index) {
    index ^= (index >> 16) & 0x0000ffffu;
    index ^= (index >> 8) & 0x00ff00ffu;
    index ^= (index >> 4) & 0x0f0f0f0fu;
    index ^= (index >> 2) & 0x33333333u;
    return index ^ ((index >> 1) & 0x55555555u);
}

}  // namespace detail

/// The point of pixel (x, y) (their 16 low bits: the pattern repeats every 65536 pixels) for the
/// random word `seed` (one per image and per stream of points): in [0, 1)^2.
///
/// Pixel (x, y) gets the point of index shuffle(morton(x, y)) of Sobol's first two dimensions (a
/// (0, 2)-sequence in base 2), each coordinate Owen-scrambled; shuffle is an Owen scrambling of the
/// index. An aligned 2^k x 2^k block of pixels has 4^k consecutive Morton codes, which the shuffle
/// maps to another 4^k consecutive, aligned indices: a (0, 2k, 2)-net, which the scrambling keeps
/// (one point in each of the block's 4^k elementary intervals [a 2^-i, (a + 1) 2^-i) x
/// [b 2^-j, (b + 1) 2^-j), i + j = 2k; in float, whose points keep 24 bits, for k <= 12). Each
/// pixel's point is uniform over [0, 1)^2 over the seeds, so a Monte Carlo sum that takes it as
/// its uniform shift (all of it, not a part: a shift that covers part of a lattice's period is
/// biased) keeps its expectation; a filter that averages neighbouring pixels' estimates then
/// averages stratified samples, whose errors partly cancel (white-noise points: they add).
template <typename T = float>
LTC_HOST_DEVICE LTC_INLINE glm::vec<2, T> screen_point(std::uint32_t x, std::uint32_t y, std::uint64_t seed) {
    const std::uint32_t index = detail::owen_scramble(detail::morton_code(x, y), static_cast<std::uint32_t>(seed));
    const std::uint32_t s0 = static_cast<std::uint32_t>(seed >> 32), s1 = s0 * 0x9e3779b9u + 0x7f4a7c15u;
    // Both coordinates Owen-scrambled, reverse(permutation(reverse(d))), where the reversed digits
    // of the first (van der Corput's: d = the index reversed) are the index itself.
    const std::uint32_t first = detail::reverse_bits(detail::lower_bits_permutation(index, s0));
    const std::uint32_t second =
        detail::reverse_bits(detail::lower_bits_permutation(detail::sobol_second_reversed(index), s1));
    return glm::vec<2, T>(detail::unit_fraction<T>(first), detail::unit_fraction<T>(second));
}

LTC_NAMESPACE_END
