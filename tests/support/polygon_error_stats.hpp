// Measured errors of the closed-form polygon integrals against the brute force, per
// distribution and precision, printed once per test case (test_polygon_integration.cpp,
// test_transformed_integration.cpp).
#pragma once

#include "support/polygon_references.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace ltc_test::polygon_integration {

struct error_stats {
    // [distribution][0: float, 1: double]
    double max_rel[4][2] = {};      // max |closed - brute| / |brute|, all polygons
    double max_rel_big[4][2] = {};  // the same over the polygons with brute >= 1e-3
    double max_abs[4][2] = {};      // max |closed - brute|
    double max_ratio[4][2] = {};    // max |closed - brute| / tolerance (asserted <= 1)
    double max_bound[4][2] = {};    // max |closed - brute| / rounding bound (informative)

    void add(int id, int t, double closed, double brute, double tol, double bound) {
        const double err = std::abs(closed - brute);
        if (brute > 0) max_rel[id][t] = std::max(max_rel[id][t], err / brute);
        if (brute >= 1e-3) max_rel_big[id][t] = std::max(max_rel_big[id][t], err / brute);
        max_abs[id][t] = std::max(max_abs[id][t], err);
        max_ratio[id][t] = std::max(max_ratio[id][t], err / tol);
        if (bound > 0) max_bound[id][t] = std::max(max_bound[id][t], err / bound);
    }

    void print(const char* title) const {
        std::ostringstream s;
        s << "\n"
          << title << "\n"
          << "  rel = max |closed - brute| / brute; rel(I>=1e-3) over integrals >= 1e-3; abs = max |closed - brute|;\n"
          << "  err/tol <= 1 is asserted (tol = brute-force estimate + rounding bound); err/bound: bound alone\n";
        s << "  " << std::left << std::setw(24) << "distribution" << std::setw(7) << "type" << std::right
          << std::setw(10) << "rel" << std::setw(15) << "rel(I>=1e-3)" << std::setw(10) << "abs" << std::setw(9)
          << "err/tol" << std::setw(11) << "err/bound"
          << "\n";
        for (int id = 0; id < 4; ++id)
            for (int t = 0; t < 2; ++t) {
                s << "  " << std::left << std::setw(24) << dist_names[id] << std::setw(7) << (t ? "double" : "float")
                  << std::right << std::scientific << std::setprecision(2) << std::setw(10) << max_rel[id][t]
                  << std::setw(15) << max_rel_big[id][t] << std::setw(10) << max_abs[id][t] << std::fixed
                  << std::setprecision(3) << std::setw(9) << max_ratio[id][t] << std::setw(11) << max_bound[id][t]
                  << "\n";
            }
        std::cout << s.str() << std::flush;
    }
};

}  // namespace ltc_test::polygon_integration
