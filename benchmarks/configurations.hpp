// The 4096 random configurations shared by bench_polygon and bench_batch: GGX-like inverse
// matrices [a 0 b; 0 c 0; d 0 1] (row-major) and rectangles in front of the shading point,
// rotated at random, so that about half cross the horizon. The library's SplitMix64 with a fixed
// seed: the same set on every machine and standard library.
#pragma once

#include <ltc/reference/ground_truth.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace bench {

struct config {
    glm::dmat3 m_inv;
    glm::dvec3 quad[4];
};

inline const std::vector<config>& configs() {
    static const std::vector<config> all = [] {
        std::vector<config> v;
        ltc::ground_truth::splitmix64 g(2016);
        for (int i = 0; i < 4096; ++i) {
            config c;
            const double a = 0.05 + g.uniform(), b = -0.5 + g.uniform(), cc = 0.05 + g.uniform(), d = -0.5 + g.uniform();
            c.m_inv = glm::transpose(glm::dmat3(a, 0, b, 0, cc, 0, d, 0, 1));
            // Drawn z, y, x: the order in which GCC evaluated the constructor arguments of the
            // first version, whose measurements the README quotes (now sequenced explicitly).
            const double cz = -0.3 + 1.3 * g.uniform();
            const double cy = -1 + 2 * g.uniform();
            const double cx = -1 + 2 * g.uniform();
            const glm::dvec3 centre(cx, cy, cz);
            const double phi = 6.283185307179586 * g.uniform();
            const double tilt = 3.141592653589793 * g.uniform();
            const glm::dvec3 ex(std::cos(phi), std::sin(phi), 0);
            const glm::dvec3 ey(-std::sin(phi) * std::cos(tilt), std::cos(phi) * std::cos(tilt), std::sin(tilt));
            const double w = 0.2 + 0.8 * g.uniform();
            const double h = 0.2 + 0.8 * g.uniform();
            c.quad[0] = centre - w * ex - h * ey;
            c.quad[1] = centre + w * ex - h * ey;
            c.quad[2] = centre + w * ex + h * ey;
            c.quad[3] = centre - w * ex + h * ey;
            v.push_back(c);
        }
        return v;
    }();
    return all;
}

}  // namespace bench
