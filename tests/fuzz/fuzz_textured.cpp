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

#include <unistd.h>

namespace {

using namespace ltc_fuzz;

template <typename T>
void run(FuzzedDataProvider& in) {
    const scene<T> sc = read_scene<T>(in);
    const shading_point<T> s = read_shading_point<T>(in);
    check_textured<T>(in, sc.m, sc.v, s.P, s.N, s.V, s.roughness);
}

}  // namespace

// glibc's get_nprocs (behind std::thread::hardware_concurrency) reads
// /sys/devices/system/cpu/online on every call, and light_texture's filter asks on every pass,
// about seven times a texture: a sixth of this harness's time went to those reads. The harness
// answers in its place (an executable's definition takes the place of libc's) with the count
// sysconf reads once (glibc's sysconf calls its own internal get_nprocs, not this one): the same
// answer, once.
extern "C" int get_nprocs() noexcept {
    static const int n = [] {
        const long c = sysconf(_SC_NPROCESSORS_ONLN);
        return c > 0 ? static_cast<int>(c) : 1;
    }();
    return n;
}

LTC_FUZZ_ENTRY(run)
