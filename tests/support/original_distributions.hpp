// The library's four original distributions in float and double: the type list of the tests
// that run on every one of them (Catch2's TEMPLATE_TEST_CASE).
#pragma once

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/squared_clamped_cosine.hpp>
#include <ltc/core/uniform_hemisphere.hpp>
#include <ltc/core/uniform_sphere.hpp>

#define LTC_ORIGINAL_DISTRIBUTIONS                                                                  \
    ltc::uniform_sphere<float>, ltc::uniform_sphere<double>, ltc::uniform_hemisphere<float>,         \
        ltc::uniform_hemisphere<double>, ltc::clamped_cosine<float>, ltc::clamped_cosine<double>, \
        ltc::squared_clamped_cosine<float>, ltc::squared_clamped_cosine<double>
