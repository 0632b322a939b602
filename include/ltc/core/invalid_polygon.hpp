// ltc/core/invalid_polygon.hpp -- the exception of the polygon samplers' checked factories
// (spherical_polygon_sampler, projected_polygon_sampler, ltc_polygon_sampler,
// polygon_area_sampler::checked): include it wherever one of them is called (ltc/ltc.hpp does).
//
//   try { auto s = ltc::ltc_polygon_sampler<float>::checked(d, vertices, n); }
//   catch (const ltc::invalid_polygon& e) { /* e.what(): the sampler, n and its max_vertices */ }
#pragma once

#include <ltc/config.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>

LTC_NAMESPACE_BEGIN

/// The vertices given to a sampler's checked factory describe no polygon it can hold: more than
/// its max_vertices (the capacity, its MaxVertices template argument), fewer than 3, or a vertex
/// that is not finite.
class invalid_polygon : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;

    /// What failed: the codes the samplers' checks pass to raise().
    enum reason { too_many_vertices, too_few_vertices, non_finite };

    /// Throws the exception for `what` of `sampler` (its name, e.g. "ltc::ltc_polygon_sampler"),
    /// given n vertices (for non_finite: the index of the first that is not finite).
    [[noreturn]] static void raise(reason what, const char* sampler, std::size_t n, std::size_t max_vertices) {
        const std::string name(sampler), count = std::to_string(n), max = std::to_string(max_vertices);
        if (what == too_many_vertices)
            throw invalid_polygon(name + ": " + count + " vertices, more than its max_vertices = " + max +
                                  " (the capacity, the MaxVertices template argument: " + name + "<T, " + count +
                                  "> holds them)");
        if (what == too_few_vertices) throw invalid_polygon(name + ": " + count + " vertices, a polygon has at least 3");
        throw invalid_polygon(name + ": vertex " + count + " is not finite");
    }
};

LTC_NAMESPACE_END
