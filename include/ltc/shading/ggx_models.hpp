// ltc/shading/ggx_models.hpp -- the GGX material models of ltc::shade (ltc/shading/shade.hpp):
// each is a type that knows its table and the lobe set its table gives (ltc/shading/lobes.hpp).
//
//   ltc::shade<ltc::ggx::one_lobe>(s, light);        // the paper's single LTC (ltc/tables/ggx.hpp)
//   ltc::shade<ltc::ggx::ltc_and_cosine>(s, light);  // the default: an LTC and the cosine
//   ltc::shade<ltc::ggx::two_lobes>(s, light);       // two LTCs
//   ltc::shade(ltc::ggx::one_lobe_of{table}, s, light);  // one LTC from a user's own ltc_table
//
// The model interface (what a user's own model provides, e.g. over its own ltc_table):
//   template <class T> using coefficients = lobes::one<T> (or ltc_and_cosine, two);
//   template <class T> static coefficients<T> fetch(T cos_theta_v, T roughness);  (or a const
//   member, the model passed as an object: ltc::shade(model, s, light), as one_lobe_of)
//   anisotropic: fetch(T cos_theta_v, T phi_v, T roughness, T roughness_bitangent) instead
//   (ltc::ggx::anisotropic, ltc/shading/ggx_anisotropic_model.hpp: the tangent frame).
// Errors of each fit: docs/results/ggx_error.md; which to choose: docs/shading.md.
#pragma once

#include <ltc/config.hpp>
#include <ltc/shading/ggx_cosine_lobe_fetch.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/ggx_two_lobe_fetch.hpp>
#include <ltc/shading/lobes.hpp>

LTC_NAMESPACE_BEGIN
namespace ggx {

/// The paper's single LTC per node (ggx::fetch, ltc/tables/ggx.hpp).
struct one_lobe {
    template <typename T>
    using coefficients = lobes::one<T>;
    template <typename T>
    static coefficients<T> fetch(T cos_theta_v, T roughness) {
        return {ggx::fetch<T>(cos_theta_v, roughness)};
    }
};

/// One LTC per node of a user's own ltc_table (ltc/tables/ltc_table.hpp: any table of that
/// layout, e.g. a refit or a copy of ggx::data in GPU memory), held by value (a pointer and two
/// ints): ltc::shade(ggx::one_lobe_of{table}, s, light) shades as shade<one_lobe> with
/// table.fetch. __host__ __device__ under CUDA: a kernel builds it over a device copy of the data.
struct one_lobe_of {
    ltc_table table;

    template <typename T>
    using coefficients = lobes::one<T>;
    template <typename T>
    LTC_HOST_DEVICE coefficients<T> fetch(T cos_theta_v, T roughness) const {
        return {table.fetch(cos_theta_v, roughness)};
    }
};

/// An LTC and the clamped cosine about the normal (ggx_cosine_lobe::fetch): the default model.
struct ltc_and_cosine {
    template <typename T>
    using coefficients = lobes::ltc_and_cosine<T>;
    template <typename T>
    static coefficients<T> fetch(T cos_theta_v, T roughness) {
        const auto c = ggx_cosine_lobe::fetch<T>(cos_theta_v, roughness);
        return {c[1], c[0]};
    }
};

/// Two LTCs per node (ggx_two_lobe::fetch).
struct two_lobes {
    template <typename T>
    using coefficients = lobes::two<T>;
    template <typename T>
    static coefficients<T> fetch(T cos_theta_v, T roughness) {
        const auto c = ggx_two_lobe::fetch<T>(cos_theta_v, roughness);
        return {c[0], c[1]};
    }
};

}  // namespace ggx
LTC_NAMESPACE_END
