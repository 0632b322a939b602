// The integrals depend on the vertices' directions only: scaling each vertex by its own power of
// two (exact: M^-1 (2^k p) = 2^k M^-1 p, no rounding changes) must not change them. This catches
// arithmetic that mixes vertices of different lengths, as a cancellation-free cross product
// p x (q -+ p) of unnormalized vertices did (q drowns in q -+ p when |p| >> |q|: an error of
// u |p| / |q|, 5% at a length ratio of 1e7; found by the fuzzer, tests/fuzz/). Every batch
// instruction set and the scalar quad path, against the unscaled scalar path, within
// ltc_test::clip_tolerance (tests/test_batch.cpp derives it; the scaled vertices have the same
// unit vectors as the unscaled ones up to the normalization's rounding).
#include "support/batch_items.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace ltc_test_batch_scaling {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test;  // support/batch_items.hpp

TEMPLATE_TEST_CASE("batch and quad path: each vertex's length does not matter", "[batch][quad]",
                   ltc::edge_policy::minimax_rational, ltc::edge_policy::polynomial) {
    using Policy = TestType;
    const std::size_t count = 2051;
    const items it = random_items(4, count, 555, true, true);
    items scaled = it;
    rng g(556);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t k = 0; k < 4; ++k) {
            // |M^-1 p|^2 of the test polygons is within [1e-3, 1e2]: 4^(+-20) keeps it in the
            // kernel's range (1e-16, 1e16); lengths of neighbours differ by up to 2^40.
            const int e = int(std::floor(g.uniform(-20, 21)));
            scaled.x[k][i] = std::ldexp(it.x[k][i], e);
            scaled.y[k][i] = std::ldexp(it.y[k][i], e);
            scaled.z[k][i] = std::ldexp(it.z[k][i], e);
        }
    for (const auto s : {ltc::sidedness::two_sided, ltc::sidedness::one_sided}) {
        // The scalar path on the scaled quads (its quad path) against the unscaled: the same check.
        std::vector<float> scalar(count);
        for (std::size_t i = 0; i < count; ++i) scalar[i] = scalar_value<Policy>(scaled.matrix(i), scaled.polygon(i), s);
        const comparison cs = compare<Policy>(it, scalar, s);
        CHECK_COMPARISON(cs, count);
        for (const auto isa : isas()) {
            CAPTURE(static_cast<int>(isa), s == ltc::sidedness::two_sided);
            std::vector<float> out(count, -1.0f);
            ltc::batch::integrate_quads<Policy>(scaled.soa<4>(scaled.per_item()), out.data(), count, s, isa);
            const comparison c = compare<Policy>(it, out, s);
            CHECK_COMPARISON(c, count);
        }
    }
}

}  // namespace ltc_test_batch_scaling
