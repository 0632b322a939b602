// common/stb.hpp -- stb_image_write and stb_image (Debian: libstb-dev, <stb/stb_image_write.h>,
// <stb/stb_image.h>): their declarations here, their implementations in stb.cpp (the one
// translation unit that holds them). GCC 12 and Clang 14 give no warning for them under -Wall
// -Wextra -Wpedantic; older or newer releases of the headers have tripped these, so they are
// silenced for the headers only.
#pragma once

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#endif
#if defined(_MSC_VER)
#pragma warning(push, 0)
#endif
#include <stb/stb_image_write.h>
#include <stb/stb_image.h>
#if defined(_MSC_VER)
#pragma warning(pop)
#endif
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
