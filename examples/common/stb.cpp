// common/stb.cpp -- the implementations of stb_image_write and stb_image (stb.hpp), compiled once
// into the object library ltc_examples_stb that the renderers link (examples/CMakeLists.txt).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#include "stb.hpp"
