// The checked factories of ltc/core/transformed.hpp reject singular and non-finite matrices with a
// clear error, and accept valid matrices of any scale (split from test_bad_input.cpp).
#include "support/bad_input.hpp"

#include <ltc/ltc.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

namespace ltc_test_checked_factories {  // the file's own names, apart from the other files of a unity batch

namespace {

template <typename T>
using vec3 = glm::vec<3, T>;
using ltc_test::edge_sum_bound;
using ltc_test::supplement_m;

}  // namespace

TEMPLATE_TEST_CASE("checked factories reject singular and non-finite matrices", "[bad-input][matrix]", float,
                   double) {
    using T = TestType;
    using mat3 = glm::mat<3, 3, T>;
    using D = ltc::transformed<ltc::clamped_cosine<T>>;
    const T inf = std::numeric_limits<T>::infinity();
    const T nan = std::numeric_limits<T>::quiet_NaN();
    mat3 rank2 = supplement_m<T>();
    rank2[2] = rank2[0] + rank2[1];  // third column in the span of the first two
    // |det| / (|c0||c1||c2|) = s / sqrt(2 + s^2): rejected below sqrt(epsilon), accepted above.
    const auto skewed = [](T s) { return mat3(vec3<T>(1, 0, 0), vec3<T>(0, 1, 0), vec3<T>(1, 1, s)); };
    const T root_eps = std::sqrt(std::numeric_limits<T>::epsilon());
    const mat3 nearly = skewed(root_eps / 4);
    CHECK_NOTHROW(D::checked(skewed(root_eps * 4)));
    // Anisotropic scaling alone is not singularity: a diagonal matrix has ratio 1.
    CHECK_NOTHROW(D::checked(mat3(vec3<T>(1e-6f, 0, 0), vec3<T>(0, 1, 0), vec3<T>(0, 0, 1))));
    mat3 with_nan = supplement_m<T>();
    with_nan[1][2] = nan;
    mat3 with_inf = supplement_m<T>();
    with_inf[0][0] = inf;
    for (const mat3& m : {mat3(T(0)), rank2, nearly, with_nan, with_inf}) {
        CHECK_THROWS_AS(D::checked(m), ltc::invalid_transform);
        CHECK_THROWS_AS(D::checked_from_inverse(m), ltc::invalid_transform);
    }
    CHECK_THROWS_WITH(D::checked(rank2), Catch::Contains("singular"));
    CHECK_THROWS_WITH(D::checked(with_nan), Catch::Contains("non-finite"));
    CHECK_THROWS_WITH(D::checked(mat3(T(0))), Catch::Contains("zero"));
    // A valid matrix of any scale, even one whose determinant would underflow, is accepted and
    // gives the same distribution as the plain constructor.
    const vec3<T> tri[3] = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}};
    const T ref = D(supplement_m<T>()).integrate(tri, 3);
    for (T scale : {T(1), T(1e-30), T(1e30)}) {
        CAPTURE(scale);
        const D d = D::checked(supplement_m<T>() * scale);
        CHECK(d.integrate(tri, 3) == Approx(ref).epsilon(edge_sum_bound<T>(3)));
        const D e = D::checked_from_inverse(glm::inverse(supplement_m<T>()) * scale);
        CHECK(e.integrate(tri, 3) == Approx(ref).epsilon(edge_sum_bound<T>(3) * 4));
    }
}

}  // namespace ltc_test_checked_factories
