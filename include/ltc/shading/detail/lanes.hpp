// ltc/shading/detail/lanes.hpp -- one polygon (or one edge) per SIMD lane: ltc/shading/detail/lanes.inc (the lane
// primitives, the edge terms of eq. (11), lane_polygon) compiled once per instruction set of
// ltc/shading/detail/simd.hpp, in ltc::detail::lanes::baseline and, on x86-64, ltc::detail::lanes::avx2 and
// ltc::detail::lanes::avx512.
// Used by the batch kernels (ltc/shading/detail/batch_simd.hpp) and the float quad path
// (ltc/core/detail/quad_lanes.hpp).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/shading/detail/simd.hpp>

#include <cstddef>
#include <limits>
#include <type_traits>

#if LTC_SIMD
LTC_NAMESPACE_BEGIN
namespace detail {
namespace lanes {

namespace baseline {
using namespace ltc::simd::baseline;
#define LTC_SIMD_FN LTC_SIMD_BASELINE_FN
#include <ltc/shading/detail/lanes.inc>
#undef LTC_SIMD_FN
}  // namespace baseline

#if LTC_SIMD_AVX2
namespace avx2 {
using namespace ltc::simd::avx2;
#define LTC_SIMD_FN LTC_SIMD_AVX2_FN
#include <ltc/shading/detail/lanes.inc>
#undef LTC_SIMD_FN
}  // namespace avx2
#endif

#if LTC_SIMD_AVX512
namespace avx512 {
using namespace ltc::simd::avx512;
#define LTC_SIMD_FN LTC_SIMD_AVX512_FN
#include <ltc/shading/detail/lanes.inc>
#undef LTC_SIMD_FN
}  // namespace avx512
#endif

}  // namespace lanes
}  // namespace detail
LTC_NAMESPACE_END
#endif  // LTC_SIMD
