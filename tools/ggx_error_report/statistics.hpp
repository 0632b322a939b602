// ggx_error_report/statistics.hpp -- relative errors |LTC - GT| / GT over the significant
// configurations (GT >= 1e-3 of the albedo), filtered by any predicate, and their mean, 95th
// percentile and max.
#pragma once

#include "grid.hpp"
#include "common/error_summary.hpp"
#include "ltc_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace ggx_error_report {

using ltc_examples::stats;
using ltc_examples::summarize;

inline bool significant(const config& c, double albedo) { return c.gt.mean >= 1e-3 * albedo; }

inline std::vector<double> rel_errors(const std::vector<config>& grid, const evaluation& ev, int m,
                                      const std::function<bool(const config&)>& keep) {
    std::vector<double> e;
    for (std::size_t i = 0; i < grid.size(); ++i)
        if (keep(grid[i]) && significant(grid[i], ev.albedo[i]))
            e.push_back(std::abs(ev.value[m][i] - grid[i].gt.mean) / grid[i].gt.mean);
    return e;
}

}  // namespace ggx_error_report
