// ltc/core/sidedness.hpp -- one- and two-sided emitters: how a signed polygon integral becomes a
// non-negative one (the paper's shader code). Signed integrals are positive when the polygon's
// vertices turn clockwise as seen from the shading point (ltc/core/polygon.hpp, conventions).
#pragma once

#include <ltc/config.hpp>

#include <cmath>

LTC_NAMESPACE_BEGIN

/// How a one-sided or two-sided emitter turns a signed integral into a non-negative one:
/// one_sided = max(0, signed), two_sided = |signed| (the paper's shader code).
enum class sidedness { one_sided, two_sided };

template <typename T>
LTC_HOST_DEVICE LTC_INLINE T apply_sidedness(T signed_value, sidedness s) {
    return s == sidedness::two_sided ? std::abs(signed_value)
                                     : (signed_value > T(0) ? signed_value : T(0));
}

LTC_NAMESPACE_END
