// The Vulkan compute runner (tests/support/vulkan_compute.hpp) on whichever device is there
// (lavapipe in CI): tests/support/vulkan_selftest.comp computes out[i] = in[i] * 2 + add, which
// the C++ here computes too, bit for bit. Without a device every test case warns and passes.
#include <catch2/catch.hpp>

#include "support/vulkan_compute.hpp"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef LTC_SPIRV_VULKAN_SELFTEST
#error "LTC_SPIRV_VULKAN_SELFTEST (the path of vulkan_selftest.spv) is defined by tests/CMakeLists.txt"
#endif
#ifndef LTC_SPIRV_VULKAN_DEVICE_PROBE
#error "LTC_SPIRV_VULKAN_DEVICE_PROBE (the path of vulkan_device_probe.spv) is defined by tests/CMakeLists.txt"
#endif

namespace ltc_test_vulkan_compute {

namespace vk = ltc_test::vulkan;

// One instance and device for the whole file: opening one costs more than a small run.
vk::context* shared_context(std::string& why_not) {
  static std::string why;
  static const std::unique_ptr<vk::context> context = [] {
    auto opened = vk::open(why);
    if (opened) {
      std::cout << "vulkan_compute: device " << opened->description() << '\n';
    }
    return opened;
  }();
  why_not = why;
  return context.get();
}

std::uint32_t bits(float x) {
  std::uint32_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

float from_bits(std::uint32_t b) {
  float x = 0.0f;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

std::vector<std::uint32_t> as_words(const std::vector<float>& values) {
  std::vector<std::uint32_t> words;
  for (float v : values) {
    words.push_back(bits(v));
  }
  return words;
}

// in[i] * 2 + add as the shader's `precise` asks: two roundings, never one fma.
float expected(float in, float add) {
  volatile float doubled = in * 2.0f;  // volatile: no contraction here either, whatever the flags
  return doubled + add;
}

struct selftest_run {
  std::vector<std::uint32_t> outputs;
  std::vector<std::uint32_t> inputs_back;
};

// Runs the self-test shader over inputs; outputs has `extra` more words than inputs, set to a
// marker the shader must leave alone (it writes only i < count).
selftest_run run_selftest(vk::context& context, const std::vector<float>& inputs, float add,
                          std::size_t extra = 0) {
  constexpr std::uint32_t marker = 0xdeadbeefu;
  std::vector<std::vector<std::uint32_t>> buffers{as_words(inputs),
                                                  std::vector<std::uint32_t>(inputs.size() + extra, marker)};
  // Groups enough for the extra words too: the shader's guard, not the dispatch, must spare them.
  const auto groups = static_cast<std::uint32_t>((inputs.size() + extra + 63) / 64);
  context.run(vk::read_spirv(LTC_SPIRV_VULKAN_SELFTEST), buffers, groups,
              {bits(add), static_cast<std::uint32_t>(inputs.size())});
  return {buffers[1], buffers[0]};
}

TEST_CASE("vulkan runner: read_spirv refuses what is not SPIR-V", "[vulkan]") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  const std::string missing = (dir / "ltc_vulkan_compute_missing.spv").string();
  std::remove(missing.c_str());
  CHECK_THROWS_WITH(vk::read_spirv(missing), Catch::Contains("cannot open"));

  const std::string odd = (dir / "ltc_vulkan_compute_odd.spv").string();
  std::ofstream(odd, std::ios::binary) << "abc";
  CHECK_THROWS_WITH(vk::read_spirv(odd), Catch::Contains("multiple of 4"));
  const std::string empty = (dir / "ltc_vulkan_compute_empty.spv").string();
  std::ofstream(empty, std::ios::binary).close();
  CHECK_THROWS_WITH(vk::read_spirv(empty), Catch::Contains("multiple of 4"));
  const std::string text = (dir / "ltc_vulkan_compute_text.spv").string();
  std::ofstream(text, std::ios::binary) << "not SPIR-V text!";  // 16 bytes
  CHECK_THROWS_WITH(vk::read_spirv(text), Catch::Contains("magic"));
  std::remove(odd.c_str());
  std::remove(empty.c_str());
  std::remove(text.c_str());

  const std::vector<std::uint32_t> words = vk::read_spirv(LTC_SPIRV_VULKAN_SELFTEST);
  REQUIRE(words.size() > 5);
  CHECK(words[0] == 0x07230203u);
}

TEST_CASE("vulkan runner: the shader's results equal the C++ bit for bit", "[vulkan]") {
  std::string why;
  vk::context* context = shared_context(why);
  if (context == nullptr) {
    WARN("skipped: no Vulkan device: " << why);
    return;
  }
  // Normal values of every magnitude and both signs, 1000 of them: not a multiple of the group
  // size, so the last group's guard matters.
  std::vector<float> inputs;
  std::uint32_t state = 12345u;
  for (int i = 0; i < 1000; ++i) {
    state = state * 1664525u + 1013904223u;
    const float mantissa = 1.0f + static_cast<float>(state >> 8) / 16777216.0f;
    const int exponent = static_cast<int>((state >> 3) % 120u) - 60;
    inputs.push_back(((state & 1u) != 0 ? -1.0f : 1.0f) * std::ldexp(mantissa, exponent));
  }
  for (float add : {0.0f, 0.1f, -3.0e5f}) {
    INFO("add = " << add);
    const selftest_run run = run_selftest(*context, inputs, add, 7);
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      if (run.outputs[i] != bits(expected(inputs[i], add))) {
        if (++mismatches <= 5) {
          UNSCOPED_INFO("in[" << i << "] = " << inputs[i] << ": device " << from_bits(run.outputs[i]) << ", C++ "
                              << expected(inputs[i], add));
        }
      }
    }
    CHECK(mismatches == 0);
    for (std::size_t i = inputs.size(); i < run.outputs.size(); ++i) {
      CHECK(run.outputs[i] == 0xdeadbeefu);  // past count: left as uploaded
    }
    CHECK(run.inputs_back == as_words(inputs));  // read back, unchanged
  }
  std::cout << "vulkan_compute: vkCreateComputePipelines " << context->last_pipeline_seconds() * 1e3
            << " ms, submit to fence " << context->last_dispatch_seconds() * 1e3 << " ms\n";
}

TEST_CASE("vulkan runner: precise keeps the product's overflow (no fma)", "[vulkan]") {
  std::string why;
  vk::context* context = shared_context(why);
  if (context == nullptr) {
    WARN("skipped: no Vulkan device: " << why);
    return;
  }
  // 0.75 * FLT_MAX * 2 overflows; an fma would give 1.5 * FLT_MAX - 0.5 * FLT_MAX = FLT_MAX.
  const float add = -0.5f * FLT_MAX;
  const selftest_run run = run_selftest(*context, {0.75f * FLT_MAX, -0.75f * FLT_MAX}, add);
  CHECK(from_bits(run.outputs[0]) == std::numeric_limits<float>::infinity());
  CHECK(from_bits(run.outputs[1]) == -std::numeric_limits<float>::infinity());
}

TEST_CASE("vulkan runner: wrong bindings and push constants throw, the buffers stay", "[vulkan]") {
  std::string why;
  vk::context* context = shared_context(why);
  if (context == nullptr) {
    WARN("skipped: no Vulkan device: " << why);
    return;
  }
  const std::vector<std::uint32_t> spirv = vk::read_spirv(LTC_SPIRV_VULKAN_SELFTEST);
  const std::vector<std::uint32_t> push{bits(1.0f), 4u};

  std::vector<std::vector<std::uint32_t>> one_buffer{as_words({1.0f, 2.0f, 3.0f, 4.0f})};
  CHECK_THROWS_WITH(context->run(spirv, one_buffer, 1, push), Catch::Contains("binding 1"));
  std::vector<std::vector<std::uint32_t>> two{as_words({1.0f, 2.0f, 3.0f, 4.0f}), std::vector<std::uint32_t>(4)};
  CHECK_THROWS_WITH(context->run(spirv, two, 1), Catch::Contains("needs 8 bytes; 0 given"));
  CHECK_THROWS_WITH(context->run(spirv, two, 1, {bits(1.0f)}), Catch::Contains("needs 8 bytes; 4 given"));
  CHECK_THROWS_WITH(context->run(spirv, two, 1, std::vector<std::uint32_t>(33)), Catch::Contains("132 bytes"));
  std::vector<std::uint32_t> broken = spirv;
  broken.resize(broken.size() / 2);
  CHECK_THROWS_AS(context->run(broken, two, 1, push), std::runtime_error);

  // A buffer the shader does not use, and an empty one (bound as 4 bytes), come back as they went.
  std::vector<std::vector<std::uint32_t>> four{as_words({1.0f, 2.0f, 3.0f, 4.0f}), std::vector<std::uint32_t>(4),
                                               {}, {7u, 8u, 9u}};
  context->run(spirv, four, 1, push);
  CHECK(four[1] == as_words({3.0f, 5.0f, 7.0f, 9.0f}));
  CHECK(four[2].empty());
  CHECK(four[3] == std::vector<std::uint32_t>{7u, 8u, 9u});

  // No work groups: nothing written, no error.
  std::vector<std::vector<std::uint32_t>> idle{as_words({1.0f}), std::vector<std::uint32_t>{42u}};
  context->run(spirv, idle, 0, {bits(1.0f), 1u});
  CHECK(idle[1] == std::vector<std::uint32_t>{42u});
}

TEST_CASE("vulkan runner: what the device does where Vulkan leaves a choice", "[vulkan]") {
  std::string why;
  vk::context* context = shared_context(why);
  if (context == nullptr) {
    WARN("skipped: no Vulkan device: " << why);
    return;
  }
  const float a = 1.0f + std::ldexp(1.0f, -12);
  const float c = -(1.0f + std::ldexp(1.0f, -11));
  const float denormal = std::ldexp(1.0f, -140);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::uint32_t loop_count = 100000;  // above llvmpipe's 65535
  std::vector<std::vector<std::uint32_t>> buffers{as_words({a, a, c, FLT_MIN, denormal, nan, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0})};
  buffers[0][6] = loop_count;
  context->run(vk::read_spirv(LTC_SPIRV_VULKAN_DEVICE_PROBE), buffers, 1);
  const std::vector<std::uint32_t>& v = buffers[0];
  const float one_rounding = std::ldexp(1.0f, -24);  // a * a + c exactly
  const float two_roundings = 0.0f;                  // a * a rounds to -c
  REQUIRE(std::fma(a, a, c) == one_rounding);

  // A fma() may be fused or not, a * b + c contracted or not; precise a * b + c is two operations.
  CHECK((from_bits(v[8]) == one_rounding || from_bits(v[8]) == two_roundings));
  CHECK((from_bits(v[9]) == one_rounding || from_bits(v[9]) == two_roundings));
  CHECK(from_bits(v[10]) == two_roundings);
  // Denormals may be flushed, results and operands.
  CHECK((from_bits(v[11]) == std::ldexp(1.0f, -127) || from_bits(v[11]) == 0.0f));
  CHECK((from_bits(v[12]) == std::ldexp(1.0f, -110) || from_bits(v[12]) == 0.0f));
  // Every iteration, or llvmpipe's cap exactly: any other count is a new way to lose iterations.
  const bool llvmpipe = context->device_name().find("llvmpipe") != std::string::npos;
  CHECK((v[15] == loop_count || (llvmpipe && v[15] == 65535u)));
  std::cout << "vulkan_compute: " << context->device_name() << ": fma() "
            << (from_bits(v[8]) == one_rounding ? "fused" : "unfused (a * b + c)") << "; a * b + c "
            << (from_bits(v[9]) == one_rounding ? "contracted" : "not contracted") << "; denormal results "
            << (from_bits(v[11]) != 0.0f ? "kept" : "flushed") << ", operands "
            << (from_bits(v[12]) != 0.0f ? "kept" : "flushed") << "; NaN + 1 "
            << (std::isnan(from_bits(v[13])) ? "NaN" : std::to_string(from_bits(v[13]))) << "; isnan(NaN) "
            << (from_bits(v[14]) == 1.0f ? "true" : "false") << "; a loop of " << loop_count << " ran "
            << v[15] << " iterations" << (v[15] != loop_count ? " (all loops of an invocation share that cap)" : "")
            << '\n';
}

}  // namespace ltc_test_vulkan_compute

