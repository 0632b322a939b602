// The shading kernel's lane stages (ltc/shading/detail/batch_simd_shading.inc) against the scalar
// functions they mirror: the frame (make_shading_frame) and the table fetch (ltc_table::fetch),
// for every instruction set this machine runs.
//
// Tolerances (u = 2^-24), derived from the operations of both sides:
//   - unit vectors: the lane normalizes by rsqrt (hardware estimate, relative error
//     <= 1.5 * 2^-12, and a Newton step: <= 1.5 e^2 + 4 u = 7.4 u) of |N|^2 (1 u), the scalar
//     path by 1 / sqrt (1.5 u) of the same: each component of n and v differs by
//     delta <= 12 u;
//   - cos theta_v = n.v: 2 sqrt(3) delta from the two vectors, plus 6 u of rounding;
//   - T1 = normalize(n x (v x (n -+ v))): with d = n -+ v, w = v x d, t = n x w, each cross
//     product component moves by 2 (delta |a| + |delta b|) + 2 u |a| |b|, and the direction of t by
//     2 |delta t| / |t|, plus the normalization's 12 u; Duff's tangent (t = 0 exactly) moves by
//     at most 8 delta (its derivatives with respect to n are below 4);
//   - T2 = n x T1: 2 (delta + |delta T1|) + 2 u;
//   - the fetch, given the same cos theta_v: the same node weights (the same operations, up to
//     FMA contraction in the AVX2 build), two levels of lerps: 8 u max |node|; where |s - nearest|
//     lies within rounding of the snap tolerance, the two sides may snap differently: + tol |node
//     difference| there.
#include "support/batch_lanes.hpp"
#include "support/rng.hpp"
#include "support/shading_tolerance.hpp"

#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/shading_frame.hpp>

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ltc_test_batch_lanes {  // the file's own names, apart from the other files of a unity batch

namespace tolerance = ltc_test::shading_tolerance;  // the frame's and the fetch's (file comment)

TEST_CASE("batch shading lanes: frame and table fetch match the scalar functions", "[batch][shading]") {
    const std::size_t count = 4096;
    ltc_test::rng g(31);
    std::vector<float> in[7];
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 N = g.direction() * g.uniform(0.5, 2.0);
        glm::dvec3 V = g.direction() * g.uniform(0.2, 5.0);
        if (i % 97 == 0) V = N * 3.0;   // V along N exactly: Duff's tangent
        if (i % 89 == 0) V = -N;        // straight from below
        const double r = i % 61 == 0 ? 0.0 : i % 59 == 0 ? 1.0 : g.uniform();  // the table's edges too
        const double v[7] = {N.x, N.y, N.z, V.x, V.y, V.z, r};
        for (int k = 0; k < 7; ++k) in[k].push_back(float(v[k]));
    }
    for (const auto isa : ltc::batch::instruction_sets) {
        if (isa == ltc::batch::isa::scalar || !ltc::batch::available(isa)) continue;
        ltc_test::lane_stage_results out;
        ltc_test::lane_stages(isa, in, out, count);
        std::size_t handed_back = 0, checked = 0;
        double worst = 0;
        for (std::size_t i = 0; i < count; ++i) {
            const glm::vec3 N(in[0][i], in[1][i], in[2][i]), V(in[3][i], in[4][i], in[5][i]);
            const ltc::shading_frame<float> f = ltc::make_shading_frame(N, V);
            if (out.fallback[i]) {
                // Only V within rounding of +-N (the kernel's |t| < 32 eps, t's direction then
                // being rounding noise): sin(N, V) far below 2^-16.
                const glm::dvec3 Nd(N), Vd(V);
                CHECK(glm::length(glm::cross(Nd, Vd)) <= 0x1.0p-16 * glm::length(Nd) * glm::length(Vd));
                ++handed_back;
                continue;
            }
            ++checked;
            const tolerance::frame_bounds tol = tolerance::frame(N, V);
            const glm::vec3 lane[3] = {{out.frame[0][i], out.frame[1][i], out.frame[2][i]},
                                       {out.frame[3][i], out.frame[4][i], out.frame[5][i]},
                                       {out.frame[6][i], out.frame[7][i], out.frame[8][i]}};
            const glm::vec3 scalar[3] = {f.t1, f.t2, f.n};
            const double bound[3] = {tol.t1, tol.t2, tol.n};
            for (int k = 0; k < 3; ++k)
                for (int c = 0; c < 3; ++c) {
                    const double err = std::abs(double(lane[k][c]) - double(scalar[k][c]));
                    CAPTURE(static_cast<int>(isa), i, k, c, lane[k][c], scalar[k][c], bound[k]);
                    CHECK(err <= bound[k]);
                    worst = std::max(worst, err / bound[k]);
                }
            CHECK(std::abs(double(out.frame[9][i]) - double(f.cos_theta_v)) <= tol.cos_theta_v);
            // The fetch, from the lane's own cos theta_v.
            const float cos_lane = out.frame[9][i];
            const ltc::ltc_coefficients<float> s = ltc::ggx::fetch(cos_lane, in[6][i]);
            const float expected[6] = {s.m_inv[0][0], s.m_inv[0][2], s.m_inv[2][0], s.m_inv[2][2], s.magnitude, s.fresnel};
            for (int c = 0; c < 6; ++c) {
                const double bound_c = tolerance::fetch(ltc::ggx::table, cos_lane, in[6][i], c);
                CAPTURE(static_cast<int>(isa), i, c, out.channel[c][i], expected[c], bound_c);
                CHECK(std::abs(double(out.channel[c][i]) - double(expected[c])) <= bound_c);
            }
        }
        // At most the points drawn with V along +-N (i % 97 == 0, i % 89 == 0) are handed back.
        CAPTURE(static_cast<int>(isa), worst);
        CHECK(handed_back <= count / 97 + count / 89 + 2);
        CHECK(checked + handed_back == count);
    }
}

}  // namespace ltc_test_batch_lanes
