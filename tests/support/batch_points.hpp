// Random shading points of the batch tests, in SoA (tests/test_batch_shade.cpp), and of the GLSL
// port's test (tests/test_glsl_port.cpp), which shades the same cases.
#pragma once

#include "support/rng.hpp"

#include <ltc/shading/batch_soa.hpp>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ltc_test {

// count random shading points in SoA (P near the origin, N and V random, some V below the
// surface, some V = N exactly), rounded to float (then widened exactly for T = double).
template <typename T>
struct points_of {
    using vec3 = glm::vec<3, T>;
    std::size_t count;
    // px py pz nx ny nz vx vy vz roughness f0 rgb albedo rgb, then (anisotropic models only)
    // tangent xyz roughness_bitangent, from a stream of their own (the first 16 as before)
    std::vector<T> a[20];
    points_of(std::size_t n, std::uint64_t seed) : count(n) {
        ltc_test::rng g(seed), h(seed ^ 0x7a6e67656e74ULL);
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec3 P(g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-0.5, 0.5));
            const glm::dvec3 N = g.direction() * g.uniform(0.5, 2.0);
            glm::dvec3 V = g.direction();
            if (glm::dot(V, N) < 0 && i % 8 != 0) V = -V;
            if (i % 101 == 0) V = N;
            const double v[16] = {P.x, P.y, P.z, N.x, N.y, N.z, V.x, V.y, V.z, g.uniform(0.02, 1.0),
                                  g.uniform(), g.uniform(), g.uniform(), g.uniform(), g.uniform(), g.uniform()};
            for (int k = 0; k < 16; ++k) a[k].push_back(T(float(v[k])));
            const glm::dvec3 t = h.direction();
            const double w[4] = {t.x, t.y, t.z, h.uniform(0.02, 1.0)};
            for (int k = 0; k < 4; ++k) a[16 + k].push_back(T(float(w[k])));
        }
    }
    vec3 vec(int c, std::size_t i) const { return vec3(a[c][i], a[c + 1][i], a[c + 2][i]); }
    ltc::batch::surfaces<T> view() const {
        return {count, {a[0].data(), a[1].data(), a[2].data()}, {a[3].data(), a[4].data(), a[5].data()},
                {a[6].data(), a[7].data(), a[8].data()}, a[9].data(), {a[10].data(), a[11].data(), a[12].data()},
                {a[13].data(), a[14].data(), a[15].data()}, {a[16].data(), a[17].data(), a[18].data()},
                a[19].data()};
    }
    ltc::batch::shading_points<T> old() const {
        const T* c[16];
        for (int k = 0; k < 16; ++k) c[k] = a[k].data();
        return ltc::batch::shading_points<T>::from_columns(c);
    }
};

}  // namespace ltc_test
