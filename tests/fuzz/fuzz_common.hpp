// The fuzz harnesses' helpers (tests/fuzz/fuzz_*.cpp): finiteness checks, fuzzed finite values,
// and the input that every harness begins with (read_scene, read_shading_point).
#pragma once

#include <ltc/core/invalid_transform.hpp>
#include <ltc/ltc.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace ltc_fuzz {


template <typename T>
void require_finite(T x, const char* what) {
    if (!std::isfinite(x)) {
        std::fprintf(stderr, "non-finite %s: %g\n", what, static_cast<double>(x));
        std::abort();
    }
}

template <typename T>
void require_finite(const glm::vec<3, T>& v, const char* what) {
    require_finite(v.x, what);  // component by component: a sum of huge finite values overflows
    require_finite(v.y, what);
    require_finite(v.z, what);
}

template <typename T>
T finite_value(FuzzedDataProvider& in) {
    // Mix ordinary values with extreme magnitudes (huge, tiny, subnormal) and exact zeros.
    T x = in.ConsumeFloatingPoint<T>();
    return std::isfinite(x) ? x : T(0);
}

// What every harness reads first (after the byte that picks float or double), in this order, so
// that one harness's inputs are meaningful seeds for another's: a matrix m (M^-1 of the LTC where
// the checked factory takes it, any finite entries), whether the factory is the inverse one, a
// point u of [0, 1)^2 and a polygon of 0..15 vertices of any finite coordinates.
template <typename T>
struct scene {
    glm::mat<3, 3, T> m;
    bool use_inverse = false;
    glm::vec<2, T> u;
    std::vector<glm::vec<3, T>> v;
};

template <typename T>
scene<T> read_scene(FuzzedDataProvider& in) {
    using vec3 = glm::vec<3, T>;
    scene<T> s;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) s.m[c][r] = finite_value<T>(in);
    s.use_inverse = in.ConsumeBool();
    const T u0 = in.ConsumeProbability<T>(), u1 = in.ConsumeProbability<T>();
    s.u = glm::vec<2, T>(u0 < T(1) ? u0 : T(0), u1 < T(1) ? u1 : T(0));
    const std::size_t n = in.ConsumeIntegralInRange<std::size_t>(0, 15);
    s.v.resize(n);
    for (auto& p : s.v) p = vec3(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    return s;
}

// Then, for the harnesses that shade: a shading point P, normal N, view V (any finite values) and
// a roughness in [0, 1].
template <typename T>
struct shading_point {
    glm::vec<3, T> P, N, V;
    T roughness;
};

template <typename T>
shading_point<T> read_shading_point(FuzzedDataProvider& in) {
    using vec3 = glm::vec<3, T>;
    shading_point<T> s;
    s.P = vec3(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    s.N = vec3(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    s.V = vec3(finite_value<T>(in), finite_value<T>(in), finite_value<T>(in));
    s.roughness = in.ConsumeProbability<T>();
    return s;
}

}  // namespace ltc_fuzz

// The entry point every harness defines (at namespace scope): run<float> or run<double>, by the
// input's first byte.
#define LTC_FUZZ_ENTRY(run)                                                          \
    extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
        FuzzedDataProvider in(data, size);                                           \
        if (in.ConsumeBool())                                                        \
            run<float>(in);                                                          \
        else                                                                         \
            run<double>(in);                                                         \
        return 0;                                                                    \
    }
