// The shading kernel's lane stages (ltc/shading/detail/batch_simd_shading.inc) run on their own, for each
// instruction set, so that tests can compare them with the scalar functions they mirror and shade
// with the very frame and coefficients the kernel used.
#pragma once

#include <ltc/shading/batch_shading.hpp>

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace ltc_test {

/// Inputs: N (3 arrays), V (3 arrays), roughness. Outputs per point: t1, t2, n (9 arrays),
/// cos_theta_v, the 6 table channels, and whether the frame hands the point back (all bits set).
template <typename T>
struct lane_stage_results_of {
    std::vector<T> frame[10];  // t1 xyz, t2 xyz, n xyz, cos_theta_v
    std::vector<T> channel[6];
    std::vector<std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>> fallback;  // a lane's width
};
using lane_stage_results = lane_stage_results_of<float>;

#define LTC_TEST_LANE_STAGES(ns, attributes)                                                                       \
    template <typename T>                                                                                          \
    attributes inline void lane_stages_##ns(const std::vector<T> (&in)[7], lane_stage_results_of<T>& out,         \
                                            std::size_t count, const ltc::ltc_table& table) {                      \
        using namespace ltc::batch::detail::ns;                                                                    \
        constexpr std::size_t W = types<T>::width;                                                                 \
        for (auto& v : out.frame) v.assign(count, T(0));                                                           \
        for (auto& v : out.channel) v.assign(count, T(0));                                                         \
        out.fallback.assign(count, 0);                                                                             \
        for (std::size_t i = 0; i + W <= count; i += W) {                                                          \
            const lane_frame<T> f({load(&in[0][i]), load(&in[1][i]), load(&in[2][i])},                            \
                                  {load(&in[3][i]), load(&in[4][i]), load(&in[5][i])});                           \
            const lane_coefficients<T> c(table, f.cos_theta_v, load(&in[6][i]));                                   \
            for (int k = 0; k < 3; ++k) {                                                                          \
                __builtin_memcpy(&out.frame[k][i], &f.t1[k], sizeof f.t1[k]);                                      \
                __builtin_memcpy(&out.frame[3 + k][i], &f.t2[k], sizeof f.t2[k]);                                  \
                __builtin_memcpy(&out.frame[6 + k][i], &f.n[k], sizeof f.n[k]);                                    \
            }                                                                                                      \
            __builtin_memcpy(&out.frame[9][i], &f.cos_theta_v, sizeof f.cos_theta_v);                              \
            for (int k = 0; k < 6; ++k) __builtin_memcpy(&out.channel[k][i], &c.value[k], sizeof c.value[k]);      \
            __builtin_memcpy(&out.fallback[i], &f.fallback, sizeof f.fallback);                                    \
        }                                                                                                          \
    }

#if LTC_SIMD
LTC_TEST_LANE_STAGES(baseline, )
#if LTC_SIMD_AVX2
LTC_TEST_LANE_STAGES(avx2, LTC_SIMD_AVX2_TARGET)
#endif
#if LTC_SIMD_AVX512
LTC_TEST_LANE_STAGES(avx512, LTC_SIMD_AVX512_TARGET)
#endif
#endif

/// The lane stages of `which` (baseline, avx2 or avx512; the caller checks ltc::batch::available),
/// the coefficients from `table` (the GGX table by default).
template <typename T>
void lane_stages(ltc::batch::isa which, const std::vector<T> (&in)[7], lane_stage_results_of<T>& out, std::size_t count,
                 const ltc::ltc_table& table = ltc::ggx::table) {
#if LTC_SIMD_AVX512
    if (which == ltc::batch::isa::avx512) return lane_stages_avx512(in, out, count, table);
#endif
#if LTC_SIMD_AVX2
    if (which == ltc::batch::isa::avx2) return lane_stages_avx2(in, out, count, table);
#endif
#if LTC_SIMD
    lane_stages_baseline(in, out, count, table);
#endif
    (void)which, (void)in, (void)out, (void)count, (void)table;
}

/// The lobe set of the kernel's old parameters: one table, two, or the cosine and an LTC.
template <int Lobes, bool Cosine, typename T>
using kernel_lobes = std::conditional_t<Lobes == 1, ltc::lobes::one<T>,
                                        std::conditional_t<Cosine, ltc::lobes::ltc_and_cosine<T>, ltc::lobes::two<T>>>;

/// The shading kernel of `which` alone over `points` with the lobe set Lobes (ltc::batch::
/// lobe_set: its tables in `tables`): points [0, returned) written, NaN in specular red where it
/// hands a point back to the scalar function.
template <typename Policy, typename Lobes, typename T, std::size_t K>
std::size_t shading_kernel(ltc::batch::isa which, const ltc::batch::detail::shading_light<T>& light,
                           const ltc::batch::surfaces<T>& points, const ltc::batch::shading_results<T>& out,
                           const ltc::ltc_table* const (&tables)[K]) {
    static_assert(int(K) == ltc::batch::lobe_set<Lobes>::tables, "one table per table of the lobe set");
    (void)which;  // only the x86 builds have kernels to choose between
#if LTC_SIMD_AVX512
    if (which == ltc::batch::isa::avx512)
        return ltc::batch::detail::run_shade_avx512<Policy, Lobes>(tables, light, points, out);
#endif
#if LTC_SIMD_AVX2
    if (which == ltc::batch::isa::avx2) return ltc::batch::detail::run_shade_avx2<Policy, Lobes>(tables, light, points, out);
#endif
#if LTC_SIMD
    return ltc::batch::detail::run_shade_baseline<Policy, Lobes>(tables, light, points, out);
#else
    (void)which, (void)light, (void)points, (void)out, (void)tables;
    return 0;
#endif
}

/// The lobe set of the kernel's old parameters: one table, two, or the cosine and an LTC.
template <int Lobes, bool Cosine, typename T>
using kernel_lobes = std::conditional_t<Lobes == 1, ltc::lobes::one<T>,
                                        std::conditional_t<Cosine, ltc::lobes::ltc_and_cosine<T>, ltc::lobes::two<T>>>;

/// The same over the old shading points, the lobe set named by the old parameters: lobe l's
/// coefficients from tables[l] (with Cosine, tables[0] the cosine lobe's, integrated as the form
/// factor, tables[1] the LTC's, premultiplied).
template <typename Policy, int Lobes, bool Cosine = false, typename T>
std::size_t shading_kernel(ltc::batch::isa which, const ltc::batch::detail::shading_light<T>& light,
                           const ltc::batch::shading_points<T>& points, const ltc::batch::shading_results<T>& out,
                           std::size_t count, const ltc::ltc_table* const (&tables)[Lobes]) {
    return shading_kernel<Policy, kernel_lobes<Lobes, Cosine, T>>(which, light,
                                                                   ltc::batch::detail::surfaces_of(points, count), out,
                                                                   tables);
}

}  // namespace ltc_test
