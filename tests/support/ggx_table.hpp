// Shared pieces of the GGX table tests (test_ggx_fetch.cpp, test_fit.cpp, test_fitted_table.cpp):
// the shipped table and the fit options it was computed with.
#pragma once

#include <ltc/fitting/fit.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/tables/ltc_table.hpp>

namespace ltc_test::table_checks {

inline constexpr int n = ltc::tables::ggx_size;
inline const ltc::ltc_table& shipped = ltc::ggx::table;

/// The table's own fit options (the defaults that ltc_fit uses).
inline ltc::fit::options table_options() {
    ltc::fit::options opt;
    opt.size = n;
    return opt;
}

}  // namespace ltc_test::table_checks
