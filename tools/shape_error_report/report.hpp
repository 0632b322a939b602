// shape_error_report/report.hpp -- the report's sections (main.cpp's file comment), each printed by
// one function of report.cpp from the evaluated grid.
#pragma once

#include "grid.hpp"
#include "statistics.hpp"

#include <vector>

namespace shape_error_report {

/// The Monte Carlo truth's relative standard error per shape (and the tube's line and cosine runs).
void print_truth_noise(const std::vector<config>& grid);

/// One shape's table: each column's mean / p95 / max over the significant configurations, overall
/// and by view angle, roughness, size, placement and horizon.
void print_breakdown(const std::vector<config>& grid, int shape, const char* title, const std::vector<column>& cols);

/// The 2017 approximation (sphere, disk) and the equal-area n-gon (disk, n = 8 ... 64) against the
/// exact shape: differences of the LTC estimates.
void print_approximations(const std::vector<config>& grid);

/// The tube configurations whose estimate exceeds the whole lobe (2 r I_line > 1).
void print_tube_overshoot(const std::vector<config>& grid);

/// The diffuse form factors against their exact values, and the spheres containing the point.
void print_diffuse_and_sanity(const std::vector<config>& grid);

/// Every configuration, one line each (--list).
void print_list(const std::vector<config>& grid);

}  // namespace shape_error_report
