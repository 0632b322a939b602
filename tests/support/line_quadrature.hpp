// Brute-force references of the thin-line integrals (test_line_integral.cpp): the integral (L1)
// of ltc/core/line_integral.hpp, int_segment g(x/|x|) d/|x|^3 dl for a density g of directions,
// by adaptive Gauss-Legendre quadrature in long double, with an error estimate; and the tests'
// random segments and error records. The integrand is (L1) itself (no angle substitution, no antiderivative, no
// clipping but the density's own zero), so it shares nothing with the closed forms but the
// definition.
#pragma once

#include "support/rng.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ltc_test {

using lvec3 = glm::vec<3, long double>;
using lmat3 = glm::mat<3, 3, long double>;

struct long_rule {
    std::vector<long double> x, w;  // on [0, 1]
};

/// Gauss-Legendre nodes and weights on [0, 1] in long double (Newton on P_n from Tricomi's guess,
/// as support/gauss_legendre.hpp, without its final rounding to double).
inline long_rule gauss_legendre_long(std::size_t n) {
    long_rule r{std::vector<long double>(n), std::vector<long double>(n)};
    const long double pi = 3.141592653589793238462643383279502884L;
    for (std::size_t i = 0; i < (n + 1) / 2; ++i) {
        long double z = std::cos(pi * (i + 0.75L) / (n + 0.5L)), dp = 0;
        for (int iter = 0; iter < 100; ++iter) {
            long double p0 = 1, p1 = z;
            for (std::size_t k = 2; k <= n; ++k) {
                const long double p2 = ((2.0L * k - 1) * z * p1 - (k - 1.0L) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1);
            const long double dz = p1 / dp;
            z -= dz;
            if (std::fabs(dz) < 4 * std::numeric_limits<long double>::epsilon()) break;
        }
        r.x[i] = (1 - z) / 2;
        r.x[n - 1 - i] = (1 + z) / 2;
        r.w[i] = r.w[n - 1 - i] = 1 / ((1 - z * z) * dp * dp);
    }
    return r;
}

struct quadrature_estimate {
    long double value = 0, error = 0;  // int f, and a bound on the error of `value`
    long double bound = 0;             // int f_bound (the integral S of the tests' tolerances)
    bool converged = true;
};

/// int_lo^hi f for f(s) = {value, bound} with 0 <= value <= bound (the bound replaces the factor of
/// f that vanishes at its kinks, so that it measures the rounding noise of f even where f -> 0), by
/// bisection until, on each piece, the 10- and 20-point rules of the value agree to `relative` of
/// the piece's bound integral (relative = max(1e-17, 64 u kappa), u long double's unit roundoff,
/// kappa the caller's relative accuracy of f: above the rounding noise of a 20-term sum), or to
/// 1e-18 of a coarse first estimate of the whole bound integral, shared out by length. A piece
/// halved 48 times is accepted as it is. The estimate is the 20-point value; its error is bounded
/// by the sum of |G20 - G10| (for f analytic on a piece, G20's error is many orders below G10's)
/// plus the rounding of the sum, 64 u value. More than 10^5 pieces (never seen) stop the
/// bisection and clear `converged`.
class adaptive_quadrature {
  public:
    using pair = std::array<long double, 2>;
    adaptive_quadrature() : g10_(gauss_legendre_long(10)), g20_(gauss_legendre_long(20)) {}

    template <typename F>
    quadrature_estimate integrate(const F& f, std::vector<long double> breaks, long double kappa = 1) const {
        std::sort(breaks.begin(), breaks.end());
        const long double total = breaks.back() - breaks.front();
        long double coarse = 0;
        for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
            for (int k = 0; k < 16; ++k) {
                const long double h = (breaks[i + 1] - breaks[i]) / 16;
                coarse += rule(g20_, f, breaks[i] + k * h, breaks[i] + (k + 1) * h)[1];
            }
        const long double u = std::numeric_limits<long double>::epsilon() / 2;
        state st{total > 0 ? 1e-18L * coarse / total : 0, std::max(1e-17L, 64 * u * kappa), 0, {}};
        for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
            if (breaks[i + 1] > breaks[i]) piece(f, breaks[i], breaks[i + 1], 0, st);
        st.q.error += 64 * u * st.q.value;
        return st.q;
    }

  private:
    struct state {
        long double floor_density, relative;
        long pieces;
        quadrature_estimate q;
    };
    template <typename F>
    static pair rule(const long_rule& r, const F& f, long double lo, long double hi) {
        pair s{0, 0};
        for (std::size_t i = 0; i < r.x.size(); ++i) {
            const pair v = f(lo + (hi - lo) * r.x[i]);
            s[0] += r.w[i] * v[0];
            s[1] += r.w[i] * v[1];
        }
        return {s[0] * (hi - lo), s[1] * (hi - lo)};
    }
    template <typename F>
    void piece(const F& f, long double lo, long double hi, int depth, state& st) const {
        const pair a = rule(g10_, f, lo, hi), b = rule(g20_, f, lo, hi);
        const long double diff = std::fabs(b[0] - a[0]);
        const bool budget = ++st.pieces < 100000;
        if (diff <= st.relative * b[1] || diff <= st.floor_density * (hi - lo) || depth >= 48 || !budget) {
            st.q.value += b[0];
            st.q.bound += b[1];
            st.q.error += diff;
            st.q.converged = st.q.converged && budget && std::isfinite(b[0]) && std::isfinite(b[1]);
            return;
        }
        const long double mid = (lo + hi) / 2;
        piece(f, lo, mid, depth + 1, st);
        piece(f, mid, hi, depth + 1, st);
    }
    long_rule g10_, g20_;
};

/// (L1) by brute force: int over the segment p1-p2 of g(x/|x|) d/|x|^3 dl, with x = p1 + s (p2 - p1),
/// dl = |p2 - p1| ds and d |p2 - p1| = |x x (p2 - p1)| = |p1 x (p2 - p1)| (the same for every x of
/// the line: computed once, without the rounding noise of x), so the integrand in s is
/// g(x/|x|) |p1 x (p2 - p1)| / |x|^3; g returns {density, bound} (see adaptive_quadrature).
/// Breaks at the foot point (where the integrand peaks, with width ~d) and at the given kinks of
/// g (fractions s in (0, 1)). x = p1 + s (p2 - p1) is known to u |p|max, so the integrand to
/// u kappa relative, kappa = 1 + |p|max / d (times g's own factor, g_kappa).
template <typename G>
quadrature_estimate integrate_line_density(const lvec3& p1, const lvec3& p2, const G& g,
                                           std::vector<long double> breaks = {}, long double g_kappa = 1) {
    static const adaptive_quadrature quadrature;
    const lvec3 e = p2 - p1;
    const long double dl = glm::length(glm::cross(p1, e));
    const auto f = [&](long double s) {
        const lvec3 x = p1 + s * e;
        const long double r = glm::length(x), k = dl / (r * r * r);
        const adaptive_quadrature::pair v = g(x / r);
        return adaptive_quadrature::pair{v[0] * k, v[1] * k};
    };
    const long double foot = -glm::dot(p1, e) / glm::dot(e, e);
    breaks.push_back(0);
    breaks.push_back(1);
    if (foot > 0 && foot < 1) breaks.push_back(foot);
    for (long double& b : breaks) b = std::min<long double>(1, std::max<long double>(0, b));
    const long double kappa = 1 + std::max(glm::length(p1), glm::length(p2)) * glm::length(e) / dl;
    return quadrature.integrate(f, breaks, kappa * g_kappa);
}

/// (L1) by brute force for the segment {foot + s v: s in [s1, s2]} given by the foot point of the
/// origin on its line and a direction v orthogonal to it: x is then known to u relative (no
/// p1 + s e cancelling next to the origin), for references of full relative accuracy.
template <typename G>
quadrature_estimate integrate_line_through(const lvec3& foot, const lvec3& v, long double s1, long double s2,
                                           const G& g) {
    static const adaptive_quadrature quadrature;
    const long double dv = glm::length(foot) * glm::length(v);  // d |v|, foot . v = 0
    const auto f = [&](long double s) {
        const lvec3 x = foot + s * v;
        const long double r = std::sqrt(glm::dot(foot, foot) + s * s * glm::dot(v, v)), k = dv / (r * r * r);
        const adaptive_quadrature::pair w = g(x / r);
        return adaptive_quadrature::pair{w[0] * k, w[1] * k};
    };
    std::vector<long double> breaks = {s1, s2};
    if (s1 < 0 && s2 > 0) breaks.push_back(0);
    return quadrature.integrate(f, breaks);
}

/// The fraction s in (0, 1) where h(p1 + s (p2 - p1)) = 0 for a linear h given by h(p1), h(p2), or
/// 0 when it has no root inside (a kink of a density clipped to h >= 0).
inline long double linear_root(long double h1, long double h2) {
    return (h1 < 0) != (h2 < 0) ? h1 / (h1 - h2) : 0;
}

inline constexpr long double pi_l = 3.141592653589793238462643383279502884L;

/// The clamped cosine as {density, bound} for the quadratures above: {max(0, z)/pi, 1/pi on z > 0}.
inline std::array<long double, 2> cosine_density(const lvec3& w) {
    return {std::max(0.0L, w.z) / pi_l, w.z > 0 ? 1 / pi_l : 0};
}

/// The condition number of a segment's line, 1 + |p|max / d (d: the distance from the origin to
/// the line, known to u |p|max only); infinite for a line through the origin.
inline long double line_kappa(const lvec3& p1, const lvec3& p2) {
    const long double d = glm::length(glm::cross(p1, p2 - p1)) / glm::length(p2 - p1);
    return 1 + std::max(glm::length(p1), glm::length(p2)) / d;
}

inline long double frobenius(const lmat3& m) {
    return std::sqrt(glm::dot(m[0], m[0]) + glm::dot(m[1], m[1]) + glm::dot(m[2], m[2]));
}

/// A random segment of one of five kinds, every fifth: generic (about half cross the horizon),
/// nearly collinear with the origin, short and far, passing close to the origin, and far along its
/// own line (d tiny relative to l).
inline std::pair<glm::dvec3, glm::dvec3> random_segment(rng& r, int i) {
    const glm::dvec3 u = r.direction();
    const glm::dvec3 v = glm::normalize(glm::cross(u, r.direction()));  // a unit vector orthogonal to u
    const double a = r.uniform(0.2, 5), b = r.uniform(0.2, 5), tiny = std::pow(10.0, -r.uniform(1, 8));
    switch (i % 5) {
        case 0: return {u * a, r.direction() * b};
        case 1: return {u * a, (u + tiny * v) * b};
        case 2: return {u * a, u * a + tiny * a * r.direction()};
        case 3: return {u * a + tiny * v, -u * b + tiny * v};
        default: return {tiny * v + a * u, tiny * v + (a + b) * u};
    }
}

inline std::string vec_str(const glm::dvec3& v) {
    std::ostringstream s;
    s << std::setprecision(17) << '(' << v.x << ", " << v.y << ", " << v.z << ')';
    return s.str();
}

/// The worst errors of a closed form against the references, printed once per test case.
struct error_record {
    // max |err| / I, all and where kappa <= 10; max |err| / (u kappa (I + S))
    double max_rel = 0, max_rel_conditioned = 0, max_ratio = 0;
    void add(double err, double value, double kappa, double scale) {
        if (value > 0) max_rel = std::max(max_rel, err / value);
        if (value > 0 && kappa <= 10) max_rel_conditioned = std::max(max_rel_conditioned, err / value);
        max_ratio = std::max(max_ratio, err / scale);
    }
    void print(const char* what, const char* type) const {
        std::cout << "  " << what << ", " << type << ": max rel err " << max_rel << " (kappa <= 10: "
                  << max_rel_conditioned << "), max err / (u kappa (I + S)) " << max_ratio << "\n";
    }
};

}  // namespace ltc_test
