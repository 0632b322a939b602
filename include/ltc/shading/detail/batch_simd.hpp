// ltc/shading/detail/batch_simd.hpp -- the batch kernels (built on ltc/shading/detail/lanes.hpp) compiled once
// per instruction set of ltc/shading/detail/simd.hpp, and their entry points: run_baseline, run_avx2 and
// run_avx512 (compiled for AVX2 + FMA, or AVX-512, whatever the translation unit's flags; call
// them only where ltc::simd::avx2::supported(), or ltc::simd::avx512::supported()).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/shading/detail/lanes.hpp>
#include <ltc/shading/detail/simd.hpp>
#include <ltc/shading/batch_lobe_set.hpp>
#include <ltc/shading/batch_soa.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <cstddef>
#include <limits>
#include <type_traits>

LTC_NAMESPACE_BEGIN
namespace batch {
namespace detail {

/// Whether the SIMD kernel evaluates Policy lane-wise: a branch-free fit on c >= 0 with the
/// symmetric extension (edge_policy::minimax_rational, edge_policy::polynomial, or a user policy
/// built on ltc::detail::symmetric_fit); the others run the scalar path.
template <typename Policy, typename T>
inline constexpr bool simd_policy = LTC_SIMD && (std::is_same_v<T, float> || std::is_same_v<T, double>) &&
                                    std::is_base_of_v<ltc::detail::symmetric_fit<Policy>, Policy>;

/// The light of a batch over many points (ltc::batch::shade), the same for every lane: its n
/// world-space vertices (x[k], y[k], z[k]) in the order the light walks them (its front the side
/// from which they turn clockwise), radiance and sidedness.
template <typename T>
struct shading_light {
    const T* x;
    const T* y;
    const T* z;
    std::size_t n;
    T radiance[3];
    bool two_sided;
};

#if LTC_SIMD

namespace baseline {
using namespace ltc::simd::baseline;
using namespace ltc::detail::lanes::baseline;
#define LTC_SIMD_FN LTC_SIMD_BASELINE_FN
#include <ltc/shading/detail/batch_simd_kernel.inc>
#include <ltc/shading/detail/batch_simd_shading.inc>
#undef LTC_SIMD_FN
}  // namespace baseline

/// Items [0, returned) through the baseline kernel (16-byte vectors).
template <typename Policy, std::size_t N, typename T>
std::size_t run_baseline(const matrices<T>& mats, std::size_t n, const T* const* x, const T* const* y,
                         const T* const* z, T* out, std::size_t count, bool two_sided) {
    return baseline::integrate_items<Policy, N>(mats, n, x, y, z, out, count, two_sided);
}

#if LTC_SIMD_AVX2
namespace avx2 {
using namespace ltc::simd::avx2;
using namespace ltc::detail::lanes::avx2;
#define LTC_SIMD_FN LTC_SIMD_AVX2_FN
#include <ltc/shading/detail/batch_simd_kernel.inc>
#include <ltc/shading/detail/batch_simd_shading.inc>
#undef LTC_SIMD_FN
}  // namespace avx2

/// Items [0, returned) through the AVX2 kernel (32-byte vectors, FMA).
template <typename Policy, std::size_t N, typename T>
LTC_SIMD_AVX2_TARGET std::size_t run_avx2(const matrices<T>& mats, std::size_t n, const T* const* x, const T* const* y,
                                          const T* const* z, T* out, std::size_t count, bool two_sided) {
    return avx2::integrate_items<Policy, N>(mats, n, x, y, z, out, count, two_sided);
}

/// Points [0, returned) through the AVX2 shading kernel, with the lobe set Lobes (batch::lobe_set)
/// and its tables.
template <typename Policy, typename Lobes, typename T>
LTC_SIMD_AVX2_TARGET std::size_t run_shade_avx2(const ltc_table* const* tables, const shading_light<T>& light,
                                                const surfaces<T>& points, const shading_results<T>& out) {
    return avx2::shade_items<Policy, Lobes, T>(tables, light, points, out);
}
#endif

#if LTC_SIMD_AVX512
namespace avx512 {
using namespace ltc::simd::avx512;
using namespace ltc::detail::lanes::avx512;
#define LTC_SIMD_FN LTC_SIMD_AVX512_FN
#include <ltc/shading/detail/batch_simd_kernel.inc>
#include <ltc/shading/detail/batch_simd_shading.inc>
#undef LTC_SIMD_FN
}  // namespace avx512

/// Items [0, returned) through the AVX-512 kernel (64-byte vectors).
template <typename Policy, std::size_t N, typename T>
LTC_SIMD_AVX512_TARGET std::size_t run_avx512(const matrices<T>& mats, std::size_t n, const T* const* x,
                                              const T* const* y, const T* const* z, T* out, std::size_t count,
                                              bool two_sided) {
    return avx512::integrate_items<Policy, N>(mats, n, x, y, z, out, count, two_sided);
}

/// Points [0, returned) through the AVX-512 shading kernel (as run_shade_avx2).
template <typename Policy, typename Lobes, typename T>
LTC_SIMD_AVX512_TARGET std::size_t run_shade_avx512(const ltc_table* const* tables, const shading_light<T>& light,
                                                    const surfaces<T>& points, const shading_results<T>& out) {
    return avx512::shade_items<Policy, Lobes, T>(tables, light, points, out);
}
#endif

/// Points [0, returned) through the baseline shading kernel (as run_shade_avx2).
template <typename Policy, typename Lobes, typename T>
std::size_t run_shade_baseline(const ltc_table* const* tables, const shading_light<T>& light, const surfaces<T>& points,
                               const shading_results<T>& out) {
    return baseline::shade_items<Policy, Lobes, T>(tables, light, points, out);
}

#endif  // LTC_SIMD

}  // namespace detail
}  // namespace batch
LTC_NAMESPACE_END
