// Half of the ABI test (main.cpp): the batch API's answers in a translation unit built as usual.
#include <ltc/shading/batch.hpp>

bool ltc_abi_test_baseline_available_simd_on() { return ltc::batch::available(ltc::batch::isa::baseline); }
ltc::batch::isa ltc_abi_test_resolved_simd_on() { return ltc::batch::resolve(ltc::batch::isa::automatic); }
