// libFuzzer harness of the textured lights (fuzz_textured.hpp): tiny textures, the exact cell
// integrals with fuzzed budgets and tolerances, and textured shading with every method give
// finite results, non-negative for non-negative textures, with finite, non-negative error bounds.
// Input: fuzz_common.hpp's read_scene and read_shading_point, then check_textured's. Build and
// run: tests/fuzz/run.sh (README.md there).
#include "fuzz_common.hpp"
#include "fuzz_textured.hpp"

#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>

namespace {

using namespace ltc_fuzz;

template <typename T>
void run(FuzzedDataProvider& in) {
    const scene<T> sc = read_scene<T>(in);
    const shading_point<T> s = read_shading_point<T>(in);
    check_textured<T>(in, sc.m, sc.v, s.P, s.N, s.V, s.roughness);
}

}  // namespace

LTC_FUZZ_ENTRY(run)
