// ggx_error_report/report.hpp -- the sections of the report after the first (main.cpp's file
// comment), each printed by one function from the grid, its ground truth and the LTC estimates.
#pragma once

#include "grid.hpp"
#include "ltc_estimate.hpp"

#include <chrono>
#include <string>
#include <vector>

namespace ggx_error_report {

inline double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// 2. and 3.: the relative errors by roughness and by view angle (breakdowns.cpp).
void print_by_roughness_and_view(const std::vector<config>& grid, const evaluation& ev);

/// 4.: lights entirely above vs partly below the horizon, the clip order, and lights entirely
/// below it (horizon.cpp).
void print_horizon(const std::vector<config>& grid, const evaluation& ev, const fetch_fn& shipped);

/// 5.: the relative errors by placement and size (breakdowns.cpp).
void print_by_placement_and_size(const std::vector<config>& grid, const evaluation& ev);

/// 6.: the clipless methods against exact LTC clipping (clipless.cpp).
void print_clipless_vs_exact(const std::vector<config>& grid, const evaluation& ev);

/// 7.: tables fitted here at the given sizes against the same ground truth (fit_sizes.cpp).
void print_fit_sizes(const std::vector<config>& grid, const evaluation& ev, const std::vector<int>& fit_sizes,
                     unsigned threads);

/// 8.: tables of the given size fitted with each named objective (l3, integrals, combined, each
/// optionally "+mag") against the same ground truth (objectives.cpp).
void print_fit_objectives(const std::vector<config>& grid, const evaluation& ev, int size,
                          const std::vector<std::string>& objectives, unsigned threads);

/// 9.: the three GGX models of ltc::shade (one_lobe, ltc_and_cosine, two_lobes), their specular
/// term against the same ground truth (models.cpp).
void print_models(const std::vector<config>& grid, const evaluation& ev);

/// 10.: the paper's GGX table, read from the folder `peers` (ggx/ltc_code_ggx.txt), against the
/// shipped one-lobe table, with the sphere approximation and with exact clipping; one line saying
/// why where the file is absent (paper_table.cpp).
void print_paper_table(const std::vector<config>& grid, const evaluation& ev, const fetch_fn& shipped,
                       const std::string& peers);

}  // namespace ggx_error_report
