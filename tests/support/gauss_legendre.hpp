// Gauss-Legendre quadrature nodes and weights on [0, 1], computed by Newton's method on the
// Legendre polynomial in long double (Golub-Welsch accuracy is not needed: Newton converges
// to the last bit from Tricomi's initial guess). An N-point rule integrates polynomials of
// degree 2N - 1 exactly; for a function analytic on a neighbourhood of [0, 1] its error falls
// geometrically with N, so the difference between an N- and a 2N-point rule bounds the error
// of the 2N-point rule with a wide margin (used as the a-posteriori error estimate in tests).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace ltc_test {

struct quadrature_rule {
    std::vector<double> x;  // nodes in (0, 1)
    std::vector<double> w;  // weights, summing to 1
};

inline quadrature_rule gauss_legendre(std::size_t n) {
    quadrature_rule r;
    r.x.resize(n);
    r.w.resize(n);
    const long double pi = 3.141592653589793238462643383279502884L;
    for (std::size_t i = 0; i < (n + 1) / 2; ++i) {
        long double z = std::cos(pi * (i + 0.75L) / (n + 0.5L));
        long double dp = 0;
        for (int iter = 0; iter < 100; ++iter) {
            long double p0 = 1, p1 = z;  // P_0, P_1
            for (std::size_t k = 2; k <= n; ++k) {
                const long double p2 = ((2.0L * k - 1) * z * p1 - (k - 1.0L) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            if (n == 1) p1 = z, p0 = 1;
            dp = n * (z * p1 - p0) / (z * z - 1);  // P_n'(z)
            const long double dz = p1 / dp;
            z -= dz;
            if (std::fabs(dz) < 1e-19L) break;
        }
        const long double w = 2 / ((1 - z * z) * dp * dp);
        // map [-1, 1] -> [0, 1]
        r.x[i] = static_cast<double>((1 - z) / 2);
        r.x[n - 1 - i] = static_cast<double>((1 + z) / 2);
        r.w[i] = r.w[n - 1 - i] = static_cast<double>(w / 2);
    }
    return r;
}

}  // namespace ltc_test
