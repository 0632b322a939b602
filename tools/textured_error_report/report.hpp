// textured_error_report/report.hpp -- the sections of the report (main.cpp's file comment), each
// printed from the grid and its results (report.cpp).
#pragma once

#include "evaluate.hpp"
#include "setup.hpp"

#include <vector>

namespace textured_error_report {

/// 1.: the Monte Carlo's noise, the full-refinement cells against it (z scores), and the
/// bilinear texture against the texel-constant one.
void print_sanity_checks(const std::vector<config>& grid, const std::vector<config_result>& res, const inputs& in);

/// 2. and 3.: every method against the truth, per texture, then the Markdown summary.
void print_methods(const std::vector<config>& grid, const std::vector<config_result>& res, const inputs& in);

/// 4.: the fetch by lobe (texture, shading and fit-only errors), its bias, and by distance,
/// orientation and view angle.
void print_fetch_breakdowns(const std::vector<config>& grid, const std::vector<config_result>& res, const inputs& in);

/// 5.: the largest texture errors of each method.
void print_worst_cases(const std::vector<config>& grid, const std::vector<config_result>& res, const inputs& in);

}  // namespace textured_error_report
