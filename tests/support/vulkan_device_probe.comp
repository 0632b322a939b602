#version 450
// What the device does where Vulkan leaves it a choice (without the float-controls execution
// modes), and one thing it should not do: fma() fused or not, a * b + c contracted or not,
// denormals kept or flushed, NaN kept or assumed away, and how many loop iterations it runs.
// tests/test_vulkan_compute.cpp prints the answers and checks each against what is allowed, so
// that a GLSL port's test can be read against them.
// v[0..6] in: a, b, c (a * b + c needs the fma's one rounding to be nonzero), FLT_MIN, a denormal,
// a NaN, a loop count (as uint); v[8..15] out.
layout(local_size_x = 1) in;

layout(std430, set = 0, binding = 0) buffer Values { float v[]; };

void main() {
  precise float fused = fma(v[0], v[1], v[2]);
  float plain = v[0] * v[1] + v[2];
  precise float separate = v[0] * v[1] + v[2];
  precise float denormal_out = v[3] * 0.5;           // a denormal result
  precise float denormal_in = v[4] * 1073741824.0;   // a denormal operand, times 2^30
  float nan_sum = v[5] + 1.0;
  v[8] = fused;
  v[9] = plain;
  v[10] = separate;
  v[11] = denormal_out;
  v[12] = denormal_in;
  v[13] = nan_sum;
  v[14] = isnan(v[5]) ? 1.0 : 0.0;
  // llvmpipe ends every loop of an invocation once they have run 65535 iterations together (Mesa's
  // LP_MAX_TGSI_LOOP_ITERATIONS): the only loop here, so its count shows the cap.
  uint wanted = floatBitsToUint(v[6]);
  uint iterations = 0u;
  for (uint i = 0u; i < wanted; ++i) {
    iterations += 1u;
  }
  v[15] = uintBitsToFloat(iterations);
}
