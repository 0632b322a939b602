// libFuzzer harness of the line, disk and sphere lights (fuzz_shapes.hpp): their integrals are
// finite and in range, their shading finite and non-negative, for any finite segment, disk,
// sphere, lobe, P, N, V and roughness.
// Input: fuzz_common.hpp's read_scene and read_shading_point, then check_shapes'. Build and run:
// tests/fuzz/run.sh (README.md there).
#include "fuzz_common.hpp"
#include "fuzz_shapes.hpp"

#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>

namespace {

using namespace ltc_fuzz;

template <typename T>
void run(FuzzedDataProvider& in) {
    const scene<T> sc = read_scene<T>(in);
    const shading_point<T> s = read_shading_point<T>(in);
    check_shapes<T>(in, sc.m, sc.v, s.P, s.N, s.V, s.roughness);
}

}  // namespace

LTC_FUZZ_ENTRY(run)
