// The cases of the restricted-LTC sampler tests (test_ltc_polygon_sampling*.cpp): nine lobes of the
// shipped GGX table, ltc::ggx::fetch(cos_theta_v, roughness) for cos_theta_v in {1, 0.5, 0.15}
// and roughness in {0.1, 0.3, 0.7}, times three polygons in the shading frame (z = normal,
// V = (sin theta_v, 0, cos theta_v)): a quad overhead, a pentagon on a wall straddling the horizon,
// and a large quad (6 x 4 at height 1). Everything in T (the fetched M^-1, the vertices) and the
// double references built from exactly those values.
#pragma once

#include "support/polygon_sampling.hpp"
#include "support/rounding_bound.hpp"

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/ltc_polygon_sampling.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/ggx_fetch.hpp>

#include <glm/glm.hpp>

#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace ltc_test::polygon_sampling {

template <typename T>
struct ltc_case {
    std::string name;
    double cos_theta_v, roughness;
    poly p;               // the polygon, rounded to T
    glm::dmat3 m_inv;     // the fetched M^-1 (entries of T)
    poly q;               // M^-1 p in double: the polygon in the cosine's space
    std::vector<double> delta;  // direction errors of M^-1 p_i / |M^-1 p_i| computed in T, in units of u_T
    ltc::transformed<ltc::clamped_cosine<T>> d;
    ltc::transformed<ltc::clamped_cosine<double>> ref;
    ltc::ltc_polygon_sampler<T> s;
    double I;      // ref.integrate(p): the closed form of I_D
    double bound;  // allowed |s.integral() - I| (test_ltc_polygon_sampling.cpp)
};

inline std::vector<named_polygon> ltc_polygons() {
    const dvec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    return {{"overhead quad", rect(dvec3(-0.3, 0.2, 1.5), x, y, 0.6, 0.5)},
            {"wall pentagon", ngon(dvec3(-1, 0.3, 0.2), y, z, 0.8, 5)},
            {"large quad", rect(dvec3(0.5, 0, 1), x, y, 3, 2)}};
}

template <typename T>
ltc_case<T> make_ltc_case(double cos_theta_v, double roughness, const named_polygon& np) {
    using ltc_test::polygon_integration::form;
    using ltc_test::polygon_integration::transformed_input_error;
    const auto c = ltc::ggx::fetch(T(cos_theta_v), T(roughness));
    const auto d = ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(c.m_inv);
    const glm::dmat3 m_inv(c.m_inv);
    const auto ref = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(m_inv);
    const poly p = rounded<T>(np.v);
    const std::vector<glm::vec<3, T>> v = as<T>(p);
    std::ostringstream name;
    name << np.name << ", cos theta_v " << cos_theta_v << ", roughness " << roughness;
    poly q;
    for (const dvec3& x : p) q.push_back(m_inv * x);
    const double u = std::numeric_limits<T>::epsilon() / 2, ud = 0x1p-53;
    // transformed_vertices: M^-1 p (4 kappa_p u, support/rounding_bound.hpp), then q / |q| (3u)
    std::vector<double> delta = transformed_input_error(m_inv, m_inv, p, u);
    for (double& x : delta) x += 3;
    ltc_case<T> r{name.str(), cos_theta_v, roughness, p, m_inv, q, delta, d, ref,
                  ltc::ltc_polygon_sampler<T>(d, v.data(), v.size()), ref.integrate(p.data(), p.size()), 0};
    // integral() = E / pi: the projected sampler's bound on M^-1 P (its inputs off by delta), /
    // pi, + 2u I for the division; the closed form's own bound in double on the same polygon.
    const std::vector<double> delta_double = transformed_input_error(m_inv, m_inv, p, ud);
    r.bound = u * (projected_bound_in_u(q, delta) / kPi + 2 * r.I) +
              ltc_test::polygon_integration::rounding_bound(form::cosine, q, delta_double, ud, r.I);
    return r;
}

template <typename T>
std::vector<ltc_case<T>> ltc_cases() {
    std::vector<ltc_case<T>> r;
    for (const double ct : {1.0, 0.5, 0.15})
        for (const double rough : {0.1, 0.3, 0.7})
            for (const named_polygon& np : ltc_polygons()) r.push_back(make_ltc_case<T>(ct, rough, np));
    return r;
}

}  // namespace ltc_test::polygon_sampling
