// The fuzz harness's checks of the line, disk and sphere lights (ltc/core/line_integral.hpp,
// ltc/core/ellipse_integral.hpp, ltc/shading/{line,tube,disk,sphere}_light.hpp), called by
// tests/fuzz/fuzz_shapes.cpp for every input.
//
// Input: the harness's fuzzed M^-1 and its first two polygon vertices (the segment, the disk's
// centre and normal, the sphere's centre; the origin where the polygon has fewer), P, N, V and
// roughness; then, consumed here, a radius (fuzzed finite value) and a sidedness byte.
// Checks, in float and double:
//   - integrate_line_cosine, integrate_line (the fuzzed lobe through the checked factory, the
//     clamped cosine where it is rejected): finite and >= 0;
//   - integrate_ellipse_cosine (centre, a, b from the vertices and the matrix's columns) and
//     ellipse_vector_form_factor: finite, within [-1, 1];
//   - integrate_disk, integrate_disk_2017 and integrate_disk_polygon (8 edges): finite, >= 0
//     after sidedness, at most 1 (plus rounding);
//   - shade_line_light, shade_tube_light, shade_disk_light, shade_sphere_light, and the same
//     lights through ltc::shade<ltc::ggx::anisotropic> with a fuzzed tangent and second
//     roughness (consumed last): finite, >= 0 per channel.
#pragma once

#include "fuzz_common.hpp"

#include <ltc/core/ellipse_integral.hpp>
#include <ltc/core/line_integral.hpp>
#include <ltc/shading/ggx_anisotropic_model.hpp>
#include <ltc/shading/lights/disk_light.hpp>
#include <ltc/shading/lights/light_error.hpp>
#include <ltc/shading/lights/line_light.hpp>
#include <ltc/shading/lights/sphere_light.hpp>
#include <ltc/shading/lights/tube_light.hpp>
#include <ltc/shading/shade.hpp>
#include <ltc/shading/disk_light.hpp>
#include <ltc/shading/line_light.hpp>
#include <ltc/shading/sphere_light.hpp>
#include <ltc/shading/tube_light.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace ltc_fuzz {

template <typename T>
void require_in(T x, T lo, T hi, const char* what) {
    require_finite(x, what);
    if (!(x >= lo && x <= hi)) {
        std::fprintf(stderr, "%s out of [%g, %g]: %g\n", what, double(lo), double(hi), double(x));
        std::abort();
    }
}

template <typename T>
void require_non_negative(const glm::vec<3, T>& v, const char* what) {
    require_finite(v, what);
    if (!(v.x >= T(0) && v.y >= T(0) && v.z >= T(0))) {
        std::fprintf(stderr, "negative %s\n", what);
        std::abort();
    }
}

template <typename T>
void check_shapes(FuzzedDataProvider& in, const glm::mat<3, 3, T>& m, const std::vector<glm::vec<3, T>>& v,
                  const glm::vec<3, T>& P, const glm::vec<3, T>& N, const glm::vec<3, T>& V, T roughness) {
    using vec3 = glm::vec<3, T>;
    const vec3 a = v.size() > 0 ? v[0] : vec3(T(0)), b = v.size() > 1 ? v[1] : vec3(T(0));
    const T radius = finite_value<T>(in);
    const ltc::sidedness side = in.ConsumeBool() ? ltc::sidedness::one_sided : ltc::sidedness::two_sided;
    auto d = ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(glm::mat<3, 3, T>(T(1)));
    try {
        d = ltc::transformed<ltc::clamped_cosine<T>>::checked_from_inverse(m);
    } catch (const ltc::invalid_transform&) {
        // the clamped cosine itself
    }
    const T slack = T(1) + T(64) * std::numeric_limits<T>::epsilon();
    const T line_cos = ltc::integrate_line_cosine(a, b), line = ltc::integrate_line(d, a, b);
    require_in(line_cos, T(0), std::numeric_limits<T>::max(), "line cosine integral");
    require_in(line, T(0), std::numeric_limits<T>::max(), "line integral");
    require_in(ltc::integrate_ellipse_cosine(a, m[0], m[1]), -slack, slack, "ellipse integral");
    const vec3 F = ltc::ellipse_vector_form_factor(a, m[0], m[1]);
    for (int c = 0; c < 3; ++c) require_in(F[c], -slack, slack, "ellipse vector form factor");
    require_in(ltc::integrate_disk(d, a, b, radius, side), T(0), slack, "disk integral");
    require_in(ltc::integrate_disk_2017(d, a, b, radius, side), T(0), slack, "disk integral (2017)");
    require_in(ltc::integrate_disk_polygon(d, a, b, radius, 8, side), T(0), slack, "disk polygon integral");
    const vec3 F0(T(0.04)), albedo(T(0.5)), radiance(T(1));
    const auto line_light = ltc::shade_line_light(P, N, V, roughness, F0, albedo, radiance, a, b, radius);
    require_non_negative(line_light.specular, "tube specular");
    require_non_negative(line_light.diffuse, "tube diffuse");
    const auto tube = ltc::shade_tube_light(P, N, V, roughness, F0, albedo, radiance, a, b, radius);
    require_non_negative(tube.specular, "tube (ribbon) specular");
    require_non_negative(tube.diffuse, "tube (ribbon) diffuse");
    const auto disk = ltc::shade_disk_light(P, N, V, roughness, F0, albedo, radiance, a, b, radius, side);
    require_non_negative(disk.specular, "disk specular");
    require_non_negative(disk.diffuse, "disk diffuse");
    const auto sphere = ltc::shade_sphere_light(P, N, V, roughness, F0, albedo, radiance, a, radius);
    require_non_negative(sphere.specular, "sphere specular");
    require_non_negative(sphere.diffuse, "sphere diffuse");
    // The same lights through ltc::shade with anisotropic GGX and any finite tangent.
    const vec3 tangent(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    const ltc::surface<T> s{P, N, V, roughness, F0, albedo, tangent, in.ConsumeProbability<T>()};
    using aniso = ltc::ggx::anisotropic;
    const auto check = [](const ltc::shading_result<T>& r, const char* specular, const char* diffuse) {
        require_non_negative(r.specular, specular);
        require_non_negative(r.diffuse, diffuse);
    };
    check(ltc::shade<aniso>(s, ltc::line_light<T>{a, b, radius, radiance}), "anisotropic line specular",
          "anisotropic line diffuse");
    check(ltc::shade<aniso>(s, ltc::tube_light<T>{a, b, radius, radiance}), "anisotropic tube specular",
          "anisotropic tube diffuse");
    check(ltc::shade<aniso>(s, ltc::sphere_light<T>{a, radius, radiance}), "anisotropic sphere specular",
          "anisotropic sphere diffuse");
    try {
        const auto disk = side == ltc::sidedness::one_sided ? ltc::disk_light<T>::one_sided(a, b, radius, radiance)
                                                            : ltc::disk_light<T>::two_sided(a, b, radius, radiance);
        check(ltc::shade<aniso>(s, disk), "anisotropic disk specular", "anisotropic disk diffuse");
    } catch (const ltc::invalid_light&) {
        // a normal the disk refuses (zero)
    }
}

}  // namespace ltc_fuzz
