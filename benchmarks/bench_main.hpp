// main() of the benchmarks built in several variants (benchmarks/CMakeLists.txt): those compiled
// with -march=x86-64-v3 (LTC_BENCH_NEEDS_X86_64_V3) refuse to run on a CPU without AVX2 or FMA,
// checked before any benchmark code runs (nothing before main uses vector code paths).
#pragma once

#include <benchmark/benchmark.h>

#include <cstdio>

#define LTC_BENCHMARK_MAIN()                                                                  \
    int main(int argc, char** argv) {                                                        \
        if (!ltc_bench::cpu_runs_this_build(argv[0])) return 0;                              \
        benchmark::Initialize(&argc, argv);                                                  \
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;                    \
        benchmark::RunSpecifiedBenchmarks();                                                 \
        benchmark::Shutdown();                                                               \
        return 0;                                                                            \
    }

namespace ltc_bench {

inline bool cpu_runs_this_build(const char* name) {
#if defined(LTC_BENCH_NEEDS_X86_64_V3)
    __builtin_cpu_init();
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) {
        std::printf("%s: compiled for x86-64-v3, this CPU lacks AVX2 or FMA; skipped\n", name);
        return false;
    }
#endif
    (void)name;
    return true;
}

}  // namespace ltc_bench
