// ltc/core/invalid_transform.hpp -- the exception of the checked factories of ltc::transformed
// (ltc/core/transformed.hpp): include it wherever transformed<>::checked() or
// checked_from_inverse() is called (ltc/ltc.hpp does).
//
//   try { auto d = ltc::transformed<ltc::clamped_cosine<float>>::checked(m); }
//   catch (const ltc::invalid_transform& e) { /* e.what() names the matrix and the failed test */ }
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/transformed.hpp>

#include <cstdio>
#include <stdexcept>
#include <string>

LTC_NAMESPACE_BEGIN

/// A matrix given to a checked factory has a non-finite entry, is zero, or is singular or
/// numerically singular (|det| / product of column norms <= sqrt(epsilon)).
class invalid_transform : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;

    /// What failed: the codes transformed<>'s checks pass to raise().
    enum reason { non_finite, zero, singular };

    /// Throws the exception for `what` of the matrix called `name` ("M" or "M^-1"); `ratio` and
    /// `threshold` are those of the singularity test.
    [[noreturn]] static void raise(reason what, const char* name, double ratio, double threshold) {
        std::string msg = std::string("ltc::transformed: ") + name;
        if (what == non_finite) throw invalid_transform(msg + " has a non-finite entry");
        if (what == zero) throw invalid_transform(msg + " is zero");
        char detail[160];
        std::snprintf(detail, sizeof detail,
                      " is singular or numerically singular (|det| / product of column norms = %g, must "
                      "exceed sqrt(epsilon) = %g)",
                      ratio, threshold);
        throw invalid_transform(msg + detail);
    }
};

LTC_NAMESPACE_END
