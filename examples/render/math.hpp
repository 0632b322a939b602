// render/math.hpp -- the vector types and angle constants that every piece of the renderer uses.
#pragma once

#include <glm/glm.hpp>

namespace render {

using glm::dvec3;
using glm::vec3;
constexpr double pi = 3.141592653589793;
constexpr double deg = pi / 180.0;

}  // namespace render
