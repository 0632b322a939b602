// common/math.hpp -- the vector types and angle constants every piece of the renderers (render,
// shadows) uses.
#pragma once

#include <glm/glm.hpp>

namespace ltc_examples {

using glm::dvec3;
using glm::vec3;
constexpr double pi = 3.141592653589793;
constexpr double deg = pi / 180.0;

}  // namespace ltc_examples
