// The fuzz harness's helpers (tests/fuzz/fuzz_integrals.cpp): finiteness checks and fuzzed
// finite values.
#pragma once

#include <ltc/core/invalid_transform.hpp>
#include <ltc/ltc.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

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

}  // namespace ltc_fuzz
