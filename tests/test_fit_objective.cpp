// Tests of the opt-in integral objective of the fit (ltc/fitting/integral_objective.hpp,
// ltc/fitting/fit_integrals.hpp): the LTC side is the library's closed form (transformed<> and
// the ltc_space shading integral), the GGX side converges to the Monte Carlo ground truth, and
// fitting with it is deterministic, finite, and leaves the default (L3) fit alone.
#include <catch2/catch.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/brdf/ggx.hpp>
#include <ltc/fitting/fit.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/polygon_light_integrals.hpp>
#include <ltc/shading/shading_frame.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace ltc_test_fit_objective {  // the file's own names, apart from the other files of a unity batch

namespace {

struct node {
    double cos_theta, alpha;
};

ltc::fit::integral_targets targets_of(const node& n, int n_b = 64, int m = 12,
                                      const ltc::fit::integral_family& family = ltc::fit::integral_family::rings()) {
    const glm::dvec3 V = ltc::brdf::view_from_cos(n.cos_theta);
    const auto mom = ltc::fit::compute_moments<ltc::brdf::ggx>(V, n.alpha, 64);
    const glm::dvec3 axis = n.cos_theta >= 1 ? glm::dvec3(0, 0, 1) : mom.average_direction;
    return ltc::fit::make_integral_targets<ltc::brdf::ggx>(V, n.alpha, axis, mom.magnitude, n_b, m, family);
}

/// The largest |G_k - GT_k| / GT_k of the targets `coarse` (the (64, 8) quadrature of
/// `model`'s integrals) over their polygons, each checked against the derived tolerance of the
/// convergence tests below (4 standard errors of the Monte Carlo ground truth, plus twice the
/// change to `fine`, the (128, 24) quadrature, plus 0.5% of G) and against `bound` G; the Monte
/// Carlo seeds are seed + k.
template <typename Model>
double quadrature_error(const Model& model, const glm::dvec3& V, double alpha, const ltc::fit::integral_targets& coarse,
                        const ltc::fit::integral_targets& fine, std::uint64_t seed, double bound) {
    REQUIRE(!coarse.polygons.empty());
    REQUIRE(coarse.polygons.size() == fine.polygons.size());
    double worst = 0;
    for (std::size_t k = 0; k < coarse.polygons.size(); ++k) {  // the same polygons, in order
        REQUIRE(coarse.polygons[k].centre == fine.polygons[k].centre);
        REQUIRE(coarse.polygons[k].planar_radius == fine.polygons[k].planar_radius);
        ltc::ground_truth::options o;
        o.samples = 1u << 12;
        o.target_relative_error = 0.004;
        o.max_samples = 1u << 20;
        o.seed = seed + k;
        const auto gt = ltc::ground_truth::integrate(model, V, alpha, coarse.polygons[k].vertices.data(), 6, o);
        const double tol = 4 * gt.standard_error + 2 * std::abs(coarse.ggx[k] - fine.ggx[k]) + 0.005 * gt.mean;
        CAPTURE(V.z, alpha, k, coarse.ggx[k], fine.ggx[k], gt.mean, gt.standard_error);
        CHECK(std::abs(coarse.ggx[k] - gt.mean) <= tol);
        CHECK(std::abs(coarse.ggx[k] - gt.mean) <= bound * gt.mean);
        worst = std::max(worst, std::abs(coarse.ggx[k] - gt.mean) / gt.mean);
    }
    return worst;
}

}  // namespace

TEST_CASE("integral objective: the family is well formed and the default objective is L3") {
    CHECK(ltc::fit::options{}.goal == ltc::fit::objective::l3);
    CHECK_FALSE(ltc::fit::options{}.fit_magnitude);
    const auto family = ltc::fit::polygon_family(glm::dvec3(-0.6, 0, 0.8), 0.25);
    CHECK(family.size() == 42);
    for (const auto& p : family) {
        CHECK(p.contains(p.centre));
        for (const auto& v : p.vertices) CHECK(std::abs(glm::length(v) - 1) < 1e-12);
        CHECK(p.pdf(p.centre) > 0);
        CHECK(p.pdf(-p.centre) == 0);
    }
}

TEST_CASE("integral objective: the spiral covering and its floor") {
    using ltc::fit::hemisphere_covering;
    const glm::dvec3 axis(-0.6, 0, 0.8);
    const auto rings = ltc::fit::polygon_family(axis, 0.25);
    const auto spiral = ltc::fit::polygon_family(axis, 0.25, hemisphere_covering::spiral);
    // The lobe's 17 hexagons, then 16 centres x 3 radii instead of the rings' 25.
    REQUIRE(spiral.size() == 17 + 48);
    for (std::size_t k = 0; k < 17; ++k) CHECK(spiral[k].centre == rings[k].centre);
    for (std::size_t i = 0; i < 16; ++i) {
        const auto& p = spiral[17 + 3 * i];
        CAPTURE(i);
        // Uniform in solid angle over the upper hemisphere, mirrored into y >= 0.
        CHECK(std::abs(p.centre.z - (i + 0.5) / 16) < 1e-12);
        // The golden angle's azimuth i 137.5 deg, mirrored into [0, 180] deg (y >= 0).
        const double golden = std::fmod(i * 137.50776405003785, 360.0);
        const double azimuth = std::atan2(p.centre.y, p.centre.x) * 180 / 3.141592653589793;
        CHECK(std::abs(azimuth - (golden > 180 ? 360 - golden : golden)) < 1e-9);
        CHECK(p.centre.y >= 0);
        for (std::size_t j = 1; j < 3; ++j) CHECK(spiral[17 + 3 * i + j].centre == p.centre);
        const double radii[] = {0.15, 0.45, 0.9};
        for (std::size_t j = 0; j < 3; ++j)
            CHECK(std::abs(std::acos(glm::dot(p.centre, spiral[17 + 3 * i + j].vertices[0])) - radii[j]) < 1e-12);
    }
    for (const auto& p : spiral)
        for (const auto& v : p.vertices) CHECK(std::abs(glm::length(v) - 1) < 1e-12);
    // Why the azimuths are mirrored rather than folded into [0, 180) deg: the centres spread more
    // evenly. The largest angle from a direction of the upper half-hemisphere (y >= 0) to its
    // nearest centre, on a 201 x 201 grid of elevations and azimuths.
    const auto largest_gap = [](const std::vector<glm::dvec3>& centres) {
        double gap = 0;
        for (int a = 0; a <= 200; ++a)
            for (int b = 0; b <= 200; ++b) {
                const double el = 0.5 * 3.141592653589793 * a / 200, az = 3.141592653589793 * b / 200;
                const glm::dvec3 d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
                double nearest = 4;
                for (const glm::dvec3& c : centres) nearest = std::min(nearest, std::acos(std::min(1.0, glm::dot(d, c))));
                gap = std::max(gap, nearest);
            }
        return gap;
    };
    std::vector<glm::dvec3> mirrored, folded;
    for (std::size_t i = 0; i < 16; ++i) {
        mirrored.push_back(spiral[17 + 3 * i].centre);
        const double el = std::asin((i + 0.5) / 16), az = std::fmod(i * 137.50776405003785, 180.0) * 3.141592653589793 / 180;
        folded.emplace_back(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    }
    const double gap_mirrored = largest_gap(mirrored), gap_folded = largest_gap(folded);
    WARN("largest angle to the nearest spiral centre: mirrored " << gap_mirrored << " rad, folded " << gap_folded << " rad");
    CHECK(gap_mirrored < 0.45);
    CHECK(gap_mirrored < gap_folded);
    // The floor goes with the family; the loss uses the targets' own.
    const node n{0.5, 0.25};
    const auto t1 = targets_of(n, 64, 8), t2 = targets_of(n, 64, 8, ltc::fit::integral_family::spiral());
    CHECK(t1.floor == 0.01);
    CHECK(t2.floor == ltc::fit::significance_threshold);
    auto t3 = t2;
    t3.floor = 0.01;
    const glm::dmat3 m_inv(1.0);  // the cosine: far from GGX's lobe, so the floor matters
    CHECK(ltc::fit::integral_loss(t2, m_inv, t2.magnitude) > ltc::fit::integral_loss(t3, m_inv, t3.magnitude));
}

TEST_CASE("integral objective: the LTC side is transformed<>::integrate and the ltc_space integral") {
    const node n{0.5, 0.25};
    const auto t = targets_of(n);
    REQUIRE(t.polygons.size() > 10);
    const glm::dvec3 V = ltc::brdf::view_from_cos(n.cos_theta);
    const auto frame = ltc::make_shading_frame(glm::dvec3(0, 0, 1), V);
    ltc::fit::ltc_parameters p;
    p.axis = glm::normalize(glm::dvec3(-0.7, 0, 0.7));
    p.m11 = 0.4, p.m22 = 0.3, p.m13 = 0.05, p.m31 = -0.1;
    const glm::dmat3 M = p.matrix();
    const glm::dmat3 m_inv = ltc::fit::invert_structured(M).inverse;
    std::vector<double> I(t.polygons.size());
    ltc::fit::ltc_integrals(t, m_inv, I.data());
    const ltc::transformed<ltc::clamped_cosine<double>> D(M);
    for (std::size_t k = 0; k < t.polygons.size(); ++k) {
        CAPTURE(k);
        const glm::dvec3* v = t.polygons[k].vertices.data();
        // Integrals are at most 1: relative 1e-12, absolute 1e-14 for those almost below the
        // horizon (where M and M^-1 round differently: up to 1e-6 relative at I ~ 1e-9).
        const double direct = D.integrate(v, 6);
        CHECK(std::abs(I[k] - direct) <= 1e-12 * direct + 1e-14);
        const double shading =
            ltc::integrate_polygon_light(frame, m_inv, glm::dvec3(0), v, 6, ltc::horizon_clipping::ltc_space).ltc;
        CHECK(std::abs(I[k] - std::abs(shading)) <= 1e-9 * I[k] + 1e-14);
    }
    // The loss is 0 for a perfect match and grows with a wrong magnitude.
    CHECK(ltc::fit::integral_loss(t, m_inv, t.magnitude) >= 0);
    CHECK(ltc::fit::integral_loss(t, m_inv, 10 * t.magnitude) > ltc::fit::integral_loss(t, m_inv, t.magnitude));
}

TEST_CASE("integral objective: the GGX side converges to the ground truth") {
    // Each family with the quadrature its fits use, (64, 8). Tolerance, derived per polygon: 4
    // standard errors of the Monte Carlo ground truth, plus twice the change of the quadrature
    // from (64, 8) to (128, 24) samples (its error is at most about that change when the finer
    // one is at least twice as accurate), plus 0.5% of G for the rest; and in any case the
    // bound integral_family states: 3% of G for the rings (measured within 2.7% on every
    // polygon of 9 nodes, 2.50% here), 4% for the spiral (3.93% here: its lowest hexagons, at
    // elevation 1.8 deg, straddle the horizon). The worst errors are printed.
    const node nodes[] = {{1.0, 0.0625}, {0.5, 0.25}, {0.17364817766693041, 0.25}, {0.17364817766693041, 1.0}};
    for (const bool spiral : {false, true}) {
        const auto family = spiral ? ltc::fit::integral_family::spiral() : ltc::fit::integral_family::rings();
        const double bound = spiral ? 0.04 : 0.03;
        double worst = 0;
        for (const node& n : nodes) {
            const auto coarse = targets_of(n, 64, 8, family), fine = targets_of(n, 128, 24, family);
            const glm::dvec3 V = ltc::brdf::view_from_cos(n.cos_theta);
            worst = std::max(worst, quadrature_error(ltc::brdf::ggx<double>{}, V, n.alpha, coarse, fine, 0xF17, bound));
        }
        WARN((spiral ? "spiral" : "rings") << ": worst relative error of the (64, 8) quadrature " << 100 * worst << "%");
    }
}

TEST_CASE("integral objective: fitting is deterministic and finite") {
    for (const auto goal : {ltc::fit::objective::integrals, ltc::fit::objective::combined}) {
        ltc::fit::options o;
        o.size = 8;
        o.goal = goal;
        o.fit_magnitude = goal == ltc::fit::objective::integrals;
        o.threads = 1;
        const std::vector<float> a = ltc::fit::fit_table<ltc::brdf::ggx>(o).packed();
        o.threads = 2;
        const std::vector<float> b = ltc::fit::fit_table<ltc::brdf::ggx>(o).packed();
        REQUIRE(a.size() == b.size());
        CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
        for (std::size_t i = 0; i < a.size(); ++i) {
            CAPTURE(i);
            REQUIRE(std::isfinite(a[i]));
        }
        for (std::size_t i = 4; i < a.size(); i += 6) CHECK(a[i] > 0);  // magnitude
    }
    // The default fit does not go through the integral objective: same node as before.
    ltc::fit::options l3;
    ltc::fit::ltc_parameters start;
    const auto r1 = ltc::fit::fit_node<ltc::brdf::ggx>(0.5, 0.25, start, l3);
    l3.fit_magnitude = true;  // ignored by the L3 objective
    const auto r2 = ltc::fit::fit_node<ltc::brdf::ggx>(0.5, 0.25, start, l3);
    CHECK(std::memcmp(&r1.m_inv, &r2.m_inv, sizeof r1.m_inv) == 0);
    CHECK(r1.magnitude == r2.magnitude);
}

TEST_CASE("integral objective: the Fresnel part's quadrature and the two-lobe fits' split of it") {
    // The Fresnel part f (1 - V.H)^5 (ltc::brdf::fresnel_part) through the quadrature the fits use,
    // (64, 8), on both families' hexagons (the rings split the two-LTC table's Fresnel term, the
    // spiral the LTC-and-cosine table's), at a grazing and a near-normal node: the tolerance of the
    // convergence test above per polygon (4 standard errors of the ground truth, twice the change
    // from (64, 8) to (128, 24), 0.5% of G), and 6% of G in any case (measured worst 5.15% on the
    // spiral, a little above f's 3.93% there, as the Fresnel part weighs the tails, whose hexagons
    // straddle the horizon, more; 4.87% on the rings).
    const node nodes[] = {{0.17364817766693041, 0.25}, {0.8660254037844387, 0.0625}};
    using fresnel = ltc::brdf::fresnel_part<ltc::brdf::ggx>;
    for (const bool spiral : {false, true}) {
        const auto family = spiral ? ltc::fit::integral_family::spiral() : ltc::fit::integral_family::rings();
        double worst = 0;
        for (const node& n : nodes) {
            const glm::dvec3 V = ltc::brdf::view_from_cos(n.cos_theta);
            const auto mom = ltc::fit::compute_moments<ltc::brdf::ggx>(V, n.alpha, 64);
            const auto t = ltc::fit::make_integral_targets<fresnel::model>(V, n.alpha, mom.average_direction, mom.fresnel, 64, 8, family);
            const auto fine =
                ltc::fit::make_integral_targets<fresnel::model>(V, n.alpha, mom.average_direction, mom.fresnel, 128, 24, family);
            // The fits take both parts' targets from one pass: the same bits as each alone.
            const auto both = ltc::fit::make_integral_targets_with_fresnel<ltc::brdf::ggx>(
                V, n.alpha, mom.average_direction, mom.magnitude, mom.fresnel, family, 64, 8);
            const auto f_alone = ltc::fit::make_integral_targets<ltc::brdf::ggx>(V, n.alpha, mom.average_direction, mom.magnitude, 64, 8, family);
            CHECK(both.first.ggx == f_alone.ggx);
            CHECK(both.second.ggx == t.ggx);
            CHECK(both.second.floor == t.floor);
            CHECK(both.second.magnitude == t.magnitude);
            worst = std::max(worst, quadrature_error(fresnel::model<double>{}, V, n.alpha, t, fine, 0xF5E, 0.06));
        }
        WARN((spiral ? "spiral" : "rings") << ", the Fresnel part: worst relative error of the (64, 8) quadrature " << 100 * worst << "%");
    }

    // The split: s_F minimizes, over [0, 1], the loss of fit_two_lobes.hpp's fresnel_share_of
    // over its targets: no point of a grid of step 1e-3 has a lower loss (up to rounding, 1e-12
    // relative). At these nodes the least-squares optimum lies inside [0, 1] for some fits and
    // outside for others (the clamp), and both occur.
    int interior = 0, clamped = 0;
    const node fits[] = {{0.17364817766693041, 0.25}, {0.5, 0.25}, {0.5, 0.5625}, {7.9632671073326335e-4, 1.0}};
    for (const auto model : {ltc::fit::two_lobe_model::ltc_and_cosine, ltc::fit::two_lobe_model::two_ltcs})
        for (const node& n : fits) {
            ltc::fit::options opt;
            ltc::fit::ltc_parameters guess;
            guess.m11 = guess.m22 = n.alpha;
            const auto one = ltc::fit::fit_node<ltc::brdf::ggx>(n.cos_theta, n.alpha, guess, opt);
            const auto start = model == ltc::fit::two_lobe_model::ltc_and_cosine ? ltc::fit::start_with_cosine(one.parameters)
                                                                               : ltc::fit::start_from_one_lobe(one.parameters);
            const auto r = ltc::fit::fit_two_lobes<ltc::brdf::ggx>(n.cos_theta, n.alpha, start, opt);
            CAPTURE(int(model), n.cos_theta, n.alpha, r.share, r.fresnel_share);
            CHECK(r.fresnel_share >= 0);
            CHECK(r.fresnel_share <= 1);
            if (!(r.share > 0) || r.share >= 1) continue;  // a dropped lobe: s_F = s
            const glm::dvec3 V = ltc::brdf::view_from_cos(n.cos_theta);
            const auto mom = ltc::fit::compute_moments<ltc::brdf::ggx>(V, n.alpha, opt.moment_samples);
            const auto t = ltc::fit::make_integral_targets_with_fresnel<ltc::brdf::ggx>(
                               V, n.alpha, mom.average_direction, mom.magnitude, r.fresnel,
                               model == ltc::fit::two_lobe_model::ltc_and_cosine ? ltc::fit::integral_family::spiral()
                                                                                 : ltc::fit::integral_family::rings())
                               .second;
            std::vector<double> i1(t.polygons.size()), i2(t.polygons.size());
            ltc::fit::ltc_integrals(t, r.m_inv[0], i1.data());
            ltc::fit::ltc_integrals(t, r.m_inv[1], i2.data());
            const auto loss = [&](double x) {
                double sum = 0;
                for (std::size_t k = 0; k < t.polygons.size(); ++k) {
                    const double e = (r.fresnel * ((1 - x) * i1[k] + x * i2[k]) - t.ggx[k]) / (t.ggx[k] + t.floor * r.fresnel);
                    sum += e * e;
                }
                return sum;
            };
            const double at = loss(r.fresnel_share);
            double best = at;
            for (int i = 0; i <= 1000; ++i) best = std::min(best, loss(i / 1000.0));
            CAPTURE(at, best, loss(r.share));
            CHECK(at <= best * (1 + 1e-12));
            CHECK(at <= loss(r.share));
            (r.fresnel_share > 0 && r.fresnel_share < 1 ? interior : clamped) += 1;
            WARN((model == ltc::fit::two_lobe_model::ltc_and_cosine ? "LTC and cosine" : "two LTCs")
                 << " at cos theta_v " << n.cos_theta << ", alpha " << n.alpha << ": share of the magnitude " << r.share
                 << ", of the Fresnel part " << r.fresnel_share << "; the Fresnel part's loss " << at << " against "
                 << loss(r.share) << " with the magnitude's share");
        }
    CHECK(interior > 0);
    CHECK(clamped > 0);
}

}  // namespace ltc_test_fit_objective
