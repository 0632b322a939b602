// The fuzz harness's checks of the textured-light paths (ltc/shading/textured_cells.hpp,
// ltc/shading/textured_light.hpp), called by tests/fuzz/fuzz_textured.cpp for every input.
//
// Input: the harness's fuzzed M^-1, polygon, P, N, V and roughness (the light is the polygon's
// first four vertices, completed by those of a unit square above the shading point where it has
// fewer), then, consumed here:
//   shape      one byte: w x h in 1..8 x 1..8, or the wide 16 x 1 and tall 1 x 16 (a byte that has
//              run out gives 1 x 1); textures stay tiny, every input builds a light_texture
//   texels     per texture a scale 2^e (e in -70..60) and its sign mode (non-negative, or for one
//              input in eight either sign); per channel one byte b: b 2^e (or int8(b) 2^e), so zero
//              texels, constant textures and ranges up to 255 2^60 all occur (no overflow of T)
//   options    sidedness, which cell integration and which shading method (one byte), budget
//              (0..64: 0 is taken as 1) and tolerance (0, or 2^-24 .. 2^7)
// Checks, in float and double:
//   - integrate_textured_cells with the fuzzed lobe (M^-1 through the checked factory, the
//     clamped cosine itself where it is rejected), budget and tolerance: value finite and, for a
//     non-negative texture, >= 0 per channel; error_bound finite and >= 0; 1 <= cells <=
//     max(budget, 1) and cells <= w h (a leaf holds at least one texel); integrals >= 1.
//   - or (a fuzzed bit) the same with budget w h and tolerance 0 (full refinement): every leaf is
//     exact (level 0, range 0 or I_D 0), so error_bound is exactly 0.
//   - integrate_textured_quad (the paper's fetch) and shade_textured_quad_light with one
//     textured_method (fuzzed; exact_cells with the fuzzed budget and tolerance): finite, and >= 0
//     per channel for a non-negative texture (F0 and albedo are).
#pragma once

#include "fuzz_common.hpp"

#include <ltc/ltc.hpp>
#include <ltc/shading/textured_cells.hpp>
#include <ltc/shading/textured_light.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace ltc_fuzz {

[[noreturn]] inline void textured_failure(const char* what, const char* where, int w, int h, double got) {
    std::fprintf(stderr, "textured %s: %s (texture %d x %d): %.9g\n", what, where, w, h, got);
    std::abort();
}

template <typename T>
void require_non_negative(const glm::vec<3, T>& v, const char* where, int w, int h) {
    for (int c = 0; c < 3; ++c)
        if (!(v[c] >= T(0))) textured_failure("negative channel", where, w, h, static_cast<double>(v[c]));
}

template <typename T>
void check_cells_result(const ltc::cells_result<T>& r, std::size_t budget, bool non_negative, int w, int h,
                        const char* where) {
    require_finite(r.value, where);
    if (non_negative) require_non_negative(r.value, where, w, h);
    require_finite(r.error_bound, where);
    if (!(r.error_bound >= T(0))) textured_failure("negative error bound", where, w, h, static_cast<double>(r.error_bound));
    if (r.cells < 1 || r.cells > std::max<std::size_t>(budget, 1) || r.cells > std::size_t(w) * std::size_t(h))
        textured_failure("cell count out of range", where, w, h, static_cast<double>(r.cells));
    if (r.integrals < 1) textured_failure("no integral", where, w, h, static_cast<double>(r.integrals));
}

template <typename T>
void check_textured(FuzzedDataProvider& in, const glm::mat<3, 3, T>& m, const std::vector<glm::vec<3, T>>& v,
                    const glm::vec<3, T>& P, const glm::vec<3, T>& N, const glm::vec<3, T>& V, T roughness) {
    using vec3 = glm::vec<3, T>;
    // The texture.
    const unsigned shape = in.ConsumeIntegral<std::uint8_t>();
    int w = 1 + int(shape & 7u), h = 1 + int((shape >> 3) & 7u);
    if ((shape >> 6) == 2u) w = 16, h = 1;
    if ((shape >> 6) == 3u) w = 1, h = 16;
    const T scale = std::ldexp(T(1), in.ConsumeIntegralInRange<int>(-70, 60));
    const bool non_negative = (in.ConsumeIntegral<std::uint8_t>() & 7u) != 0u;
    std::vector<vec3> rgb(std::size_t(w) * std::size_t(h));
    for (vec3& t : rgb)
        for (int c = 0; c < 3; ++c) {
            const std::uint8_t b = in.ConsumeIntegral<std::uint8_t>();
            t[c] = non_negative ? T(b) * scale : T(static_cast<std::int8_t>(b)) * scale;
        }
    const ltc::light_texture<T> tex(w, h, rgb.data());

    // The light: the polygon's first four vertices, the rest from a unit square at z = 1.
    vec3 quad[4] = {vec3(T(-0.5), T(-0.5), T(1)), vec3(T(0.5), T(-0.5), T(1)), vec3(T(0.5), T(0.5), T(1)),
                    vec3(T(-0.5), T(0.5), T(1))};
    for (std::size_t k = 0; k < 4 && k < v.size(); ++k) quad[k] = v[k];

    // The lobe: the fuzzed M^-1 where the checked factory takes it, else the clamped cosine.
    auto d = ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(glm::mat<3, 3, T>(T(1)));
    try {
        d = ltc::transformed<ltc::clamped_cosine<T>>::checked_from_inverse(m);
    } catch (const ltc::invalid_transform&) {
    }

    const unsigned opts = in.ConsumeIntegral<std::uint8_t>();
    const ltc::sidedness side = (opts & 1u) ? ltc::sidedness::one_sided : ltc::sidedness::two_sided;
    ltc::cell_budget budget;
    budget.max_cells = in.ConsumeIntegralInRange<std::size_t>(0, 64);
    const unsigned tol = in.ConsumeIntegral<std::uint8_t>();
    budget.tolerance = tol < 128u ? 0.0 : std::ldexp(1.0, int(tol & 31u) - 24);

    // One of the two cell integrations and one shading method per input (opts' bits 1 to 3): over a
    // run they cover all, at less cost per input than running them all.
    const auto& cells = tex.cells();
    if ((opts & 2u) == 0u) {
        check_cells_result(ltc::integrate_textured_cells(d, quad, cells, side, budget), budget.max_cells, non_negative,
                           w, h, "integrate_textured_cells");
    } else {
        ltc::cell_budget full;
        full.max_cells = std::size_t(w) * std::size_t(h);
        const auto r_full = ltc::integrate_textured_cells(d, quad, cells, side, full);
        check_cells_result(r_full, full.max_cells, non_negative, w, h, "integrate_textured_cells (full refinement)");
        if (r_full.error_bound != T(0))
            textured_failure("non-zero error bound after full refinement", "integrate_textured_cells", w, h,
                             static_cast<double>(r_full.error_bound));
    }

    const vec3 fetched = ltc::integrate_textured_quad(d, quad, tex, side);
    require_finite(fetched, "integrate_textured_quad (fetch)");
    if (non_negative) require_non_negative(fetched, "integrate_textured_quad (fetch)", w, h);

    constexpr ltc::textured_method methods[] = {ltc::textured_method::fetch, ltc::textured_method::quick_cells,
                                                ltc::textured_method::exact_cells};
    {
        const auto method = methods[((opts >> 2) & 3u) % 3u];
        ltc::textured_policy policy;
        policy.method = method;
        policy.budget = budget;
        const char* where = method == ltc::textured_method::fetch         ? "shade_textured_quad_light (fetch)"
                            : method == ltc::textured_method::quick_cells ? "shade_textured_quad_light (quick_cells)"
                                                                          : "shade_textured_quad_light (exact_cells)";
        const auto r = ltc::shade_textured_quad_light(P, N, V, roughness, vec3(T(0.04)), vec3(T(0.5)), quad, tex, side,
                                                      policy);
        require_finite(r.specular, where);
        require_finite(r.diffuse, where);
        if (non_negative) {
            require_non_negative(r.specular, where, w, h);
            require_non_negative(r.diffuse, where, w, h);
        }
    }
}

}  // namespace ltc_fuzz
