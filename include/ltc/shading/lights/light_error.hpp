// ltc/shading/lights/light_error.hpp -- the exception the lights' checked constructors throw
// (ltc::polygon_light<T>::one_sided and the others): input that describes no light, such as an
// emission normal that is zero, not finite or in the light's plane.
#pragma once

#include <ltc/config.hpp>

#include <stdexcept>
#include <string>

LTC_NAMESPACE_BEGIN

struct invalid_light : std::invalid_argument {
    explicit invalid_light(const std::string& what) : std::invalid_argument("ltc: " + what) {}
};

LTC_NAMESPACE_END
