// Minimal consumer of ltc: checks that the package is usable from outside.
#include <ltc/ltc.hpp>

#include <cmath>
#include <cstdio>

int main()
{
    const glm::dvec3 tri[3] = {
        glm::dvec3(0.0, 0.0, 1.0),
        glm::dvec3(1.0, 0.0, 1.0),
        glm::dvec3(1.0, 1.0, 1.0),
    };
    const double e = ltc::clamped_cosine<double>::integrate(tri, 3);
    std::printf("ltc_consumer: clamped_cosine<double>::integrate = %.17g\n", e);
    return (std::isfinite(e) && e > 0.0) ? 0 : 1;
}
