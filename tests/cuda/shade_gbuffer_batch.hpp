// tests/cuda/shade_gbuffer_batch.hpp -- the CPU batch side of shade_gbuffer_check.cu: the same
// G-buffer and lights through ltc::batch::shade<ltc::ggx::one_lobe>, timed. It lives in its own
// translation unit (shade_gbuffer_batch.cpp) compiled by the host compiler alone, because ltc's
// batches run in SIMD lanes only outside nvcc (__CUDACC__ leaves them the scalar path,
// ltc/shading/detail/simd.hpp): the ratio against the device is against the batch a CPU renderer
// would use. The two translation units share the names of ltc's inline functions (the ABI tag of
// ltc/config.hpp tells LTC_NO_SIMD apart, not __CUDACC__), though nvcc's definitions hold the
// lanes of ltc/core/detail/f32x4.hpp as a plain struct and the host compiler's as a vector: the
// linker keeps one of each, and both give the same bits (f32x4.hpp, quad_lanes.hpp), so the
// host side of shade_gbuffer_check.cu's comparison (a) is the same whichever it keeps.
#pragma once

#include <ltc/shading/surface.hpp>

#include <glm/glm.hpp>

#include <vector>

/// Which polygon_light factory a light of the check is built with.
enum class light_kind { counter_clockwise_front, clockwise_front, two_sided };

struct light_spec {
    std::vector<glm::vec3> vertices;
    light_kind kind;
    glm::vec3 radiance;
};

struct batch_run {
    /// Light l's contribution to point i at [l * points + i].
    std::vector<ltc::shading_result<float>> per_light;
    double seconds_per_pass = 0;  ///< every light over every point, the mean of the timed passes
    int passes = 0;               ///< timed passes (after one untimed warm-up pass)
    const char* isa = "";         ///< the instruction set batch::shade ran with (isa::automatic)
};

/// Every light over every point with ltc::batch::shade<ltc::ggx::one_lobe> (one call per light,
/// the batch's shape for a G-buffer pass), on one thread: a warm-up pass whose results are
/// returned, then timed passes until min_seconds have passed (at least one).
batch_run shade_gbuffer_batch(const std::vector<ltc::surface<float>>& points, const std::vector<light_spec>& lights,
                              double min_seconds);
