// Half of the ABI test (main.cpp): the same functions of the batch API in a translation unit
// built with LTC_NO_SIMD, where only the scalar path exists.
#define LTC_NO_SIMD
#include <ltc/shading/batch.hpp>

bool ltc_abi_test_baseline_available_simd_off() { return ltc::batch::available(ltc::batch::isa::baseline); }
int ltc_abi_test_resolved_simd_off() { return int(ltc::batch::resolve(ltc::batch::isa::automatic)); }
