// libFuzzer harness of the polygon samplers (fuzz_sampling.hpp: projected solid angle, restricted
// LTC, light area): finite directions, densities and inverses for any finite polygon and lobe.
// Input: fuzz_common.hpp's read_scene, then check_sampling's. Build and run: tests/fuzz/run.sh
// (README.md there).
#include "fuzz_common.hpp"
#include "fuzz_sampling.hpp"

#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>

namespace {

using namespace ltc_fuzz;

template <typename T>
void run(FuzzedDataProvider& in) {
    const scene<T> sc = read_scene<T>(in);
    check_sampling<T>(in, sc.m, sc.v);
}

}  // namespace

LTC_FUZZ_ENTRY(run)
