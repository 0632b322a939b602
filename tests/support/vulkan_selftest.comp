#version 450
// The Vulkan runner's self-test (tests/test_vulkan_compute.cpp): out[i] = in[i] * 2 + add.
// precise: without it the compiler may contract the two operations into an fma, which does not
// overflow where in[i] * 2 does; the test checks that it does not.
layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Inputs { float inputs[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Outputs { float outputs[]; };
layout(push_constant) uniform Constants {
  float add;
  uint count;
} constants;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= constants.count) {
    return;
  }
  precise float result = inputs[i] * 2.0 + constants.add;
  outputs[i] = result;
}
