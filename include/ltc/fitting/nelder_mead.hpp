// ltc/fitting/nelder_mead.hpp -- the fit's minimizer: Nelder-Mead over R^Dim, deterministic.
//
// The Lagarias et al. 1998 variant with the standard coefficients (reflection 1, expansion 2,
// contraction 1/2, shrink 1/2), for any callable double(const std::array<double, Dim>&). Ties are
// broken by vertex order and NaN values count as +infinity, so that the same objective gives the
// same minimum bit for bit. ltc/fitting/fit_node.hpp runs it on the LTC parameters.
#pragma once

#include <ltc/config.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

LTC_NAMESPACE_BEGIN
namespace fit {

template <std::size_t Dim>
struct nelder_mead_result {
    std::array<double, Dim> x{};  ///< best point
    double value = 0;             ///< objective at x
    int evaluations = 0;
};

/// Minimizes f over R^Dim from the simplex {start, start + step_i e_i}. Deterministic (ties are
/// broken by vertex order); NaN values count as +infinity. Stops when
/// (f_worst - f_best) <= tolerance * (|f_best| + |f_worst|) / 2 (+ a tiny absolute floor), or
/// after max_evaluations evaluations of f.
template <std::size_t Dim, typename F>
nelder_mead_result<Dim> nelder_mead(F&& f, const std::array<double, Dim>& start, const std::array<double, Dim>& step,
                                    double tolerance, int max_evaluations) {
    using point = std::array<double, Dim>;
    constexpr std::size_t n = Dim + 1;
    std::array<point, n> s;
    std::array<double, n> fs;
    int evaluations = 0;
    const auto eval = [&](const point& p) {
        ++evaluations;
        const double v = f(p);
        return v == v ? v : std::numeric_limits<double>::infinity();
    };
    for (std::size_t i = 0; i < n; ++i) {
        s[i] = start;
        if (i > 0) s[i][i - 1] += step[i - 1];
        fs[i] = eval(s[i]);
    }
    std::array<std::size_t, n> order;
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    const auto sort = [&] {
        // Stable insertion sort by value: deterministic ordering of equal values.
        for (std::size_t i = 1; i < n; ++i)
            for (std::size_t j = i; j > 0 && fs[order[j]] < fs[order[j - 1]]; --j) std::swap(order[j], order[j - 1]);
    };
    const auto combine = [](const point& a, const point& b, double t) {  // a + t (b - a)
        point r;
        for (std::size_t k = 0; k < Dim; ++k) r[k] = a[k] + t * (b[k] - a[k]);
        return r;
    };
    for (;;) {
        sort();
        const std::size_t best = order[0], worst = order[n - 1], second = order[n - 2];
        const double lo = fs[best], hi = fs[worst];
        if (hi - lo <= tolerance * 0.5 * (std::abs(lo) + std::abs(hi)) + 1e-300) break;
        if (evaluations >= max_evaluations) break;
        point c{};
        for (std::size_t i = 0; i + 1 < n; ++i)
            for (std::size_t k = 0; k < Dim; ++k) c[k] += s[order[i]][k];
        for (std::size_t k = 0; k < Dim; ++k) c[k] /= double(Dim);
        const point xr = combine(c, s[worst], -1.0);
        const double fr = eval(xr);
        if (fr < lo) {
            const point xe = combine(c, s[worst], -2.0);
            const double fe = eval(xe);
            if (fe < fr)
                s[worst] = xe, fs[worst] = fe;
            else
                s[worst] = xr, fs[worst] = fr;
            continue;
        }
        if (fr < fs[second]) {
            s[worst] = xr, fs[worst] = fr;
            continue;
        }
        if (fr < hi) {  // outside contraction
            const point xc = combine(c, xr, 0.5);
            const double fc = eval(xc);
            if (fc <= fr) {
                s[worst] = xc, fs[worst] = fc;
                continue;
            }
        } else {  // inside contraction
            const point xc = combine(c, s[worst], 0.5);
            const double fc = eval(xc);
            if (fc < hi) {
                s[worst] = xc, fs[worst] = fc;
                continue;
            }
        }
        for (std::size_t i = 1; i < n; ++i) {  // shrink towards the best vertex
            const std::size_t v = order[i];
            s[v] = combine(s[best], s[v], 0.5);
            fs[v] = eval(s[v]);
        }
    }
    sort();
    nelder_mead_result<Dim> r;
    r.x = s[order[0]];
    r.value = fs[order[0]];
    r.evaluations = evaluations;
    return r;
}

}  // namespace fit
LTC_NAMESPACE_END
