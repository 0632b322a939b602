// shape_error_report/statistics.hpp -- mean, 95th percentile and max of a sample of errors; which
// configurations count (significant: truth >= 1e-3 of the albedo, as in ggx_error_report); and a
// column of a table: a name and the relative error of one configuration.
#pragma once

#include "grid.hpp"
#include "common/error_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace shape_error_report {

using ltc_examples::stats;
using ltc_examples::summarize;

/// In the statistics: a grid configuration (not a sanity line) whose truth is at least 1e-3 of the
/// directional albedo (the others are invisible next to any light that faces the lobe).
inline bool significant(const config& c) { return !c.inside && c.gt.mean >= 1e-3 * c.albedo; }

inline double relative(double value, double truth) { return std::abs(value - truth) / truth; }

/// A column of a table: its name and the error of one configuration.
struct column {
    const char* name;
    std::function<double(const config&)> error;
};

/// The errors of one column over the significant configurations of `shape` that `keep` accepts.
inline std::vector<double> errors(const std::vector<config>& grid, int shape, const column& col,
                                  const std::function<bool(const config&)>& keep) {
    std::vector<double> e;
    for (const config& c : grid)
        if (c.shape == shape && significant(c) && keep(c)) e.push_back(col.error(c));
    return e;
}

}  // namespace shape_error_report
