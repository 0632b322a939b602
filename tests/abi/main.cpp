// One program, two translation units that disagree on LTC_NO_SIMD (simd_on.cpp, simd_off.cpp):
// the inline functions they share by name (ltc::batch::available, resolve) have different bodies.
// Without the ABI namespace of ltc/config.hpp the linker keeps one body for both (an ODR
// violation: at -O0 neither is inlined, so both files call the one it kept). With it each file
// keeps its own, and each gives its own build's answer. Built at -O0 (tests/abi/CMakeLists.txt).
#include <ltc/shading/batch.hpp>

#include <cstdio>

bool ltc_abi_test_baseline_available_simd_on();
ltc::batch::isa ltc_abi_test_resolved_simd_on();
bool ltc_abi_test_baseline_available_simd_off();
int ltc_abi_test_resolved_simd_off();

int main() {
    int failures = 0;
    if (ltc_abi_test_baseline_available_simd_off() || ltc_abi_test_resolved_simd_off() != int(ltc::batch::isa::scalar)) {
        std::printf("FAIL: the LTC_NO_SIMD translation unit ran another build's batch API\n");
        ++failures;
    }
#if LTC_SIMD
    if (!ltc_abi_test_baseline_available_simd_on() || ltc_abi_test_resolved_simd_on() == ltc::batch::isa::scalar) {
        std::printf("FAIL: the SIMD translation unit ran the LTC_NO_SIMD build's batch API\n");
        ++failures;
    }
#endif
    std::printf("%d passed, %d failed\n", 2 - failures, failures);
    return failures == 0 ? 0 : 1;
}
