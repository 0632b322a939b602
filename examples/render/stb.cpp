// render/stb.cpp -- the implementations of stb_image_write and stb_image (stb.hpp), compiled once.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#include "stb.hpp"
