// The faces of a cube around the origin tile the sphere: each subtends 4 pi / 6, and every
// distribution, original or transformed, integrates to 1 over the six faces, within the summed
// rounding bounds of support/rounding_bound.hpp.
#include <ltc/ltc.hpp>

#include "support/polygon_references.hpp"
#include "support/rounding_bound.hpp"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace ltc_test_polygon_cube {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::polygon_integration;  // support/polygon_references.hpp and the bound

TEST_CASE("cube: each face subtends 4 pi / 6, and every distribution integrates to 1 over the six faces",
          "[polygon][integration][cube]") {
    // the faces of [-1, 1]^3, wound with the positive convention (clockwise seen from the centre)
    std::vector<poly_t> faces;
    for (int axis = 0; axis < 3; ++axis)
        for (const double side : {-1.0, 1.0}) {
            poly_t f;
            for (const auto& uv : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
                dvec3 p;
                p[axis] = side;
                p[(axis + 1) % 3] = uv.x;
                p[(axis + 2) % 3] = uv.y;
                f.push_back(p);
            }
            if (glm::dot(f[0], glm::cross(f[1] - f[0], f[2] - f[0])) < 0) f = reversed(f);
            faces.push_back(f);
        }
    for (const poly_t& f : faces) {
        const auto vd = to<double>(f);
        const auto vf = to<float>(f);
        // tolerance: rounding bound of the solid angle (Omega = 4 pi I)
        const double bd = 4 * kPi * rounding_bound(form::sphere, f, {}, unit_roundoff<double>(), 1.0 / 6);
        const double bf = 4 * kPi * rounding_bound(form::sphere, f, {}, unit_roundoff<float>(), 1.0 / 6);
        const std::string face = str(f);
        CAPTURE(face, bd, bf);
        CHECK(std::abs(ltc::solid_angle(vd.data(), 4) - 4 * kPi / 6) <= bd);
        CHECK(std::abs(ltc::solid_angle(vf.data(), 4) - 4 * kPi / 6) <= bf);
    }
    // Sum over the faces: 1 for every distribution (they are normalized), original and
    // transformed. Tolerance: the sum of the faces' rounding bounds, plus 5 u_double for the
    // five additions done here in double.
    std::vector<named_matrix> ms = test_matrices();
    ms.insert(ms.begin(), named_matrix{"identity", dmat3(1)});
    for (const named_matrix& nm : ms) {
        const dmat3 m_inv = glm::inverse(nm.m);
        const dmat3 used_d(ltc::transformed<ltc::clamped_cosine<double>>(nm.m).inverse_matrix());
        const dmat3 used_f(ltc::transformed<ltc::clamped_cosine<float>>(glm::mat3(nm.m)).inverse_matrix());
        const double ud = unit_roundoff<double>(), uf = unit_roundoff<float>();
        for (int id = 0; id < 4; ++id) {
            double sum_f = 0, sum_d = 0, sum_of = 0, sum_od = 0, bound_f = 0, bound_d = 0, bound_of = 0, bound_od = 0;
            for (const poly_t& f : faces) {
                const auto vd = to<double>(f);
                const auto vf = to<float>(f);
                const poly_t q = transform(m_inv, f);
                double face_d = 0, face_f = 0;
                switch (id) {
                    case sphere:
                        face_d = ltc::transformed<ltc::uniform_sphere<double>>(nm.m).integrate(vd.data(), 4);
                        face_f = ltc::transformed<ltc::uniform_sphere<float>>(glm::mat3(nm.m)).integrate(vf.data(), 4);
                        break;
                    case hemisphere:
                        face_d = ltc::transformed<ltc::uniform_hemisphere<double>>(nm.m).integrate(vd.data(), 4);
                        face_f =
                            ltc::transformed<ltc::uniform_hemisphere<float>>(glm::mat3(nm.m)).integrate(vf.data(), 4);
                        break;
                    case cosine:
                        face_d = ltc::transformed<ltc::clamped_cosine<double>>(nm.m).integrate(vd.data(), 4);
                        face_f = ltc::transformed<ltc::clamped_cosine<float>>(glm::mat3(nm.m)).integrate(vf.data(), 4);
                        break;
                    default:
                        face_d = ltc::transformed<ltc::squared_clamped_cosine<double>>(nm.m).integrate(vd.data(), 4);
                        face_f = ltc::transformed<ltc::squared_clamped_cosine<float>>(glm::mat3(nm.m))
                                     .integrate(vf.data(), 4);
                }
                sum_d += face_d;
                sum_f += face_f;
                bound_d += rounding_bound(form_of(id), q, transformed_input_error(m_inv, used_d, f, ud), ud, face_d);
                bound_f += rounding_bound(form_of(id), q, transformed_input_error(m_inv, used_f, f, uf), uf, face_f,
                                          default_factor_error<float>(id));
                if (nm.name == std::string("identity")) {
                    const double od = closed_form<double>(id, f), of = closed_form<float>(id, f);
                    sum_od += od;
                    sum_of += of;
                    bound_od += rounding_bound(form_of(id), f, {}, ud, od);
                    bound_of += rounding_bound(form_of(id), f, {}, uf, of, default_factor_error<float>(id));
                }
            }
            const char* distribution = dist_names[id];
            const std::string matrix = str(nm.m);
            CAPTURE(distribution, matrix, sum_d, sum_f, bound_d, bound_f);
            CHECK(std::abs(sum_d - 1) <= bound_d + 5 * ud);
            CHECK(std::abs(sum_f - 1) <= bound_f + 5 * ud);
            if (nm.name == std::string("identity")) {
                CAPTURE(sum_od, sum_of, bound_od, bound_of);
                CHECK(std::abs(sum_od - 1) <= bound_od + 5 * ud);
                CHECK(std::abs(sum_of - 1) <= bound_of + 5 * ud);
            }
        }
    }
}

}  // namespace ltc_test_polygon_cube
