// render/math.hpp -- what every piece of the renderer uses: the vector types and angle constants
// of examples/common/math.hpp, and the helpers it shares with the shadows example
// (examples/common/: colour, images, seeds, threads, the command line) by their plain names.
#pragma once

#include "common/math.hpp"

namespace render {

using namespace ltc_examples;

}  // namespace render
