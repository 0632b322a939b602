// A minimal Vulkan compute runner for tests: run one SPIR-V compute shader over a few storage
// buffers on whichever Vulkan device is there (lavapipe, a CPU device, in CI) and read the buffers
// back, so that a test can compare a GLSL port with the C++ it ports.
//
// Contract:
//   * open(why_not) makes a Vulkan 1.1 instance and a logical device on the first physical device
//     (in the loader's order, any type) that has Vulkan 1.1 and a queue family with compute. It
//     returns nullptr and says why in why_not where there is no driver (the loader finds no ICD),
//     no instance, no such device, or the device cannot be created: the caller skips and says so.
//     It never throws for want of Vulkan. (The loader itself, libvulkan.so.1, is linked with
//     -lvulkan: a program without it does not start, which the build avoids by building the
//     Vulkan tests only where find_package(Vulkan) finds it.)
//   * context::run(spirv, buffers, groups_x, push_constants) runs entry point "main" of spirv
//     with storage buffer i (std430 words) at set 0, binding i, for each i; every buffer is
//     uploaded before the dispatch and read back into the same vector after it, so an output is a
//     buffer of the right size that the shader writes. The push constants (at most 128 bytes) are
//     at offset 0 for the compute stage. It dispatches (groups_x, 1, 1) and waits on a fence.
//     Before any Vulkan call it reads the shader's interface from the SPIR-V: a binding without
//     a buffer, a set other than 0, push constants shorter than the shader's block, or no entry
//     point "main" throws, where the device would run on undefined behaviour. Every failure throws
//     std::runtime_error naming the call and its VkResult (or the limit broken); the objects of the
//     run are released on every path.
//   * A run that outlasts timeout_seconds() (a shader that never ends) throws, and leaves the
//     context unusable: its objects may still be in use by the device, so they are leaked rather
//     than destroyed, later runs throw, and the destructor leaves the device and instance alone.
//   * LTC_VULKAN_VALIDATE=1 in the environment enables VK_LAYER_KHRONOS_validation where it is
//     installed (a note on stderr where it is not); a run during which the layer reports an error
//     then throws with the messages, so a test cannot pass on undefined behaviour.
//   * read_spirv(path) reads a .spv file as words; it throws where the file is missing, empty, not
//     a multiple of 4 bytes, or does not start with SPIR-V's magic number.
// Everything is created per run (module, layouts, pipeline, buffers, commands, fence): a test
// runs few shaders, and a run shares nothing that a failed one could have left half made.
//
// On lavapipe (Mesa 22.3's llvmpipe, what CI runs), as tests/test_vulkan_compute.cpp measures:
//   * The loops of one invocation run at most 65535 iterations all together (Mesa's
//     LP_MAX_TGSI_LOOP_ITERATIONS, shared by every loop of the shader); past that each loop exits
//     after one pass, silently. Keep an invocation's total below it (spread the work over more
//     invocations), or have the shader write its iteration counts for the test to check.
//   * fma() is a * b + c with two roundings, precise or not, and a * b + c is not contracted:
//     results are those of C++ with -ffp-contract=off (the project's default), not of std::fma.
//   * Denormals (operands and results), infinities, NaN and signed zeros are kept.
//   * vkCreateComputePipelines takes well under a millisecond; LLVM compiles the shader at its
//     first dispatch (some 25-50 ms on 2 cores), which Mesa's shader cache
//     (~/.cache/mesa_shader_cache) then answers in under one.
#pragma once

#include <vulkan/vulkan.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ltc_test::vulkan {

inline const char* result_name(VkResult result) {
  switch (result) {
#define LTC_VULKAN_RESULT(name) \
  case name: return #name;
    LTC_VULKAN_RESULT(VK_SUCCESS)
    LTC_VULKAN_RESULT(VK_NOT_READY)
    LTC_VULKAN_RESULT(VK_TIMEOUT)
    LTC_VULKAN_RESULT(VK_EVENT_SET)
    LTC_VULKAN_RESULT(VK_EVENT_RESET)
    LTC_VULKAN_RESULT(VK_INCOMPLETE)
    LTC_VULKAN_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    LTC_VULKAN_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    LTC_VULKAN_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    LTC_VULKAN_RESULT(VK_ERROR_DEVICE_LOST)
    LTC_VULKAN_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    LTC_VULKAN_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    LTC_VULKAN_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    LTC_VULKAN_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    LTC_VULKAN_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    LTC_VULKAN_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    LTC_VULKAN_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    LTC_VULKAN_RESULT(VK_ERROR_FRAGMENTED_POOL)
    LTC_VULKAN_RESULT(VK_ERROR_UNKNOWN)
    LTC_VULKAN_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
    LTC_VULKAN_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    LTC_VULKAN_RESULT(VK_ERROR_FRAGMENTATION)
    LTC_VULKAN_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    LTC_VULKAN_RESULT(VK_ERROR_INVALID_SHADER_NV)
#undef LTC_VULKAN_RESULT
    default: return "VkResult";
  }
}

namespace detail {

[[noreturn]] inline void fail(const std::string& what) { throw std::runtime_error("vulkan: " + what); }

[[noreturn]] inline void fail(const char* call, VkResult result) {
  fail(std::string(call) + " failed: " + result_name(result) + " (" + std::to_string(result) + ")");
}

inline void check(VkResult result, const char* call) {
  if (result != VK_SUCCESS) {
    fail(call, result);
  }
}

// A handle that the device destroys (or frees) when it goes: the run's objects are released on
// every path out of run(), the throwing ones included. release() lets one go on purpose, where the
// device may still be using it.
template <typename Handle>
class owned {
 public:
  using destroy_fn = void (*)(VkDevice, Handle, const VkAllocationCallbacks*);
  owned(VkDevice device, destroy_fn destroy) : device_(device), destroy_(destroy) {}
  owned(const owned&) = delete;
  owned& operator=(const owned&) = delete;
  owned(owned&& other) noexcept
      : device_(other.device_), destroy_(other.destroy_), handle_(std::exchange(other.handle_, Handle{})) {}
  owned& operator=(owned&&) = delete;
  ~owned() {
    if (handle_ != Handle{}) {
      destroy_(device_, handle_, nullptr);
    }
  }
  Handle* out() { return &handle_; }
  Handle get() const { return handle_; }
  void release() { handle_ = Handle{}; }

 private:
  VkDevice device_;
  destroy_fn destroy_;
  Handle handle_{};
};

inline bool env_is(const char* name, const char* value) {
  const char* set = std::getenv(name);
  return set != nullptr && std::strcmp(set, value) == 0;
}

inline std::string version_string(std::uint32_t version) {
  return std::to_string(VK_API_VERSION_MAJOR(version)) + "." + std::to_string(VK_API_VERSION_MINOR(version)) + "." +
         std::to_string(VK_API_VERSION_PATCH(version));
}

inline const char* device_type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

inline bool has_layer(const char* name) {
  std::uint32_t count = 0;
  if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) {
    return false;
  }
  std::vector<VkLayerProperties> layers(count);
  if (vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) {
    return false;
  }
  return std::any_of(layers.begin(), layers.begin() + count,
                     [&](const VkLayerProperties& layer) { return std::strcmp(layer.layerName, name) == 0; });
}

inline bool has_instance_extension(const char* layer, const char* name) {
  std::uint32_t count = 0;
  if (vkEnumerateInstanceExtensionProperties(layer, &count, nullptr) != VK_SUCCESS) {
    return false;
  }
  std::vector<VkExtensionProperties> extensions(count);
  if (vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()) != VK_SUCCESS) {
    return false;
  }
  return std::any_of(extensions.begin(), extensions.begin() + count,
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

inline bool has_device_extension(VkPhysicalDevice device, const char* name) {
  std::uint32_t count = 0;
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr) != VK_SUCCESS) {
    return false;
  }
  std::vector<VkExtensionProperties> extensions(count);
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()) != VK_SUCCESS) {
    return false;
  }
  return std::any_of(extensions.begin(), extensions.begin() + count,
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

constexpr std::uint32_t spirv_magic = 0x07230203u;
constexpr std::size_t max_push_constant_bytes = 128;  // the least maxPushConstantsSize Vulkan allows

// The shader's interface against what run() binds, read from the SPIR-V itself: without the
// validation layer a binding with no buffer behind it, or push constants shorter than the shader's
// block, is undefined behaviour that lavapipe answers with a crash or garbage, not an error. The
// block's extent is exact for scalar and vector members; a member of another type counts 4 bytes
// (a lower bound: the check then only misses more).
inline void check_interface(const std::vector<std::uint32_t>& spirv, std::uint32_t bindings,
                            std::size_t push_bytes) {
  constexpr std::uint32_t op_entry_point = 15, op_type_int = 21, op_type_float = 22, op_type_vector = 23,
                          op_type_struct = 30, op_type_pointer = 32, op_variable = 59, op_decorate = 71,
                          op_member_decorate = 72;
  constexpr std::uint32_t decoration_binding = 33, decoration_descriptor_set = 34, decoration_offset = 35;
  constexpr std::uint32_t model_gl_compute = 5, storage_push_constant = 9;
  if (spirv.size() < 5) {
    fail("run: the SPIR-V has no header (" + std::to_string(spirv.size()) + " words)");
  }
  const std::uint32_t bound = spirv[3];  // every id is below it
  if (bound > (1u << 20)) {               // no test's shader has a million ids: a corrupt header
    fail("run: malformed SPIR-V (an id bound of " + std::to_string(bound) + ")");
  }
  std::vector<std::uint32_t> scalar_bytes(bound, 0), pointee(bound, 0);
  std::vector<std::vector<std::uint32_t>> members(bound);
  std::vector<std::pair<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>>> offsets;  // struct, member, offset
  std::vector<std::uint32_t> push_pointers;
  bool has_main = false;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sets, binds;  // (variable id, value)
  for (std::size_t at = 5; at < spirv.size();) {
    const std::uint32_t count = spirv[at] >> 16, opcode = spirv[at] & 0xffffu;
    if (count == 0 || at + count > spirv.size()) {
      fail("run: malformed SPIR-V (an instruction of " + std::to_string(count) + " words at word " +
           std::to_string(at) + " of " + std::to_string(spirv.size()) + ")");
    }
    const std::uint32_t* word = &spirv[at];
    const bool defines = count >= 2 && word[1] < bound;
    if (opcode == op_entry_point && count >= 4 && word[1] == model_gl_compute) {
      const char* name = reinterpret_cast<const char*>(word + 3);
      has_main = has_main || std::strncmp(name, "main", (count - 3) * 4) == 0;
    } else if ((opcode == op_type_int || opcode == op_type_float) && count >= 3 && defines) {
      scalar_bytes[word[1]] = word[2] / 8;
    } else if (opcode == op_type_vector && count >= 4 && defines && word[2] < bound) {
      scalar_bytes[word[1]] = scalar_bytes[word[2]] * word[3];
    } else if (opcode == op_type_struct && defines) {
      members[word[1]].assign(word + 2, word + count);
    } else if (opcode == op_type_pointer && count >= 4 && defines && word[2] == storage_push_constant) {
      pointee[word[1]] = word[3];
    } else if (opcode == op_variable && count >= 4 && word[3] == storage_push_constant) {
      push_pointers.push_back(word[1]);
    } else if (opcode == op_decorate && count >= 4 && word[2] == decoration_descriptor_set) {
      sets.emplace_back(word[1], word[3]);
    } else if (opcode == op_decorate && count >= 4 && word[2] == decoration_binding) {
      binds.emplace_back(word[1], word[3]);
    } else if (opcode == op_member_decorate && count >= 5 && word[3] == decoration_offset) {
      offsets.push_back({word[1], {word[2], word[4]}});
    }
    at += count;
  }
  if (!has_main) {
    fail("run: the SPIR-V has no GLCompute entry point named main");
  }
  for (std::uint32_t pointer : push_pointers) {
    const std::uint32_t block = pointer < bound ? pointee[pointer] : 0;
    std::size_t extent = 4;
    for (const auto& offset : offsets) {
      if (block != 0 && offset.first == block && offset.second.first < members[block].size()) {
        const std::uint32_t type = members[block][offset.second.first];
        const std::uint32_t bytes = type < bound && scalar_bytes[type] != 0 ? scalar_bytes[type] : 4;
        extent = std::max<std::size_t>(extent, std::size_t{offset.second.second} + bytes);
      }
    }
    if (push_bytes < extent) {
      fail("run: the shader's push-constant block needs " + std::to_string(extent) + " bytes; " +
           std::to_string(push_bytes) + " given");
    }
  }
  for (const auto& set : sets) {
    if (set.second != 0) {
      fail("run: the shader uses descriptor set " + std::to_string(set.second) + "; only set 0 is bound");
    }
  }
  for (const auto& bind : binds) {
    if (bind.second >= bindings) {
      fail("run: the shader uses binding " + std::to_string(bind.second) + " but only " +
           std::to_string(bindings) + " buffer(s) were given");
    }
  }
}

}  // namespace detail

class context;
std::unique_ptr<context> open(std::string& why_not);

class context {
 public:
  context(const context&) = delete;
  context& operator=(const context&) = delete;

  ~context() {
    if (wedged_) {
      return;  // the device may still run the timed-out shader: waiting could hang, destroying is UB
    }
    if (device_ != VK_NULL_HANDLE) {
      vkDeviceWaitIdle(device_);
      vkDestroyDevice(device_, nullptr);
    }
    if (messenger_ != VK_NULL_HANDLE) {
      auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
      if (destroy != nullptr) {
        destroy(instance_, messenger_, nullptr);
      }
    }
    if (instance_ != VK_NULL_HANDLE) {
      vkDestroyInstance(instance_, nullptr);
    }
  }

  std::string device_name() const { return properties_.deviceName; }

  // The device in a line: its name, type, Vulkan version and driver, for the test's log.
  std::string description() const {
    return std::string(properties_.deviceName) + " (" + detail::device_type_name(properties_.deviceType) +
           ", Vulkan " + detail::version_string(properties_.apiVersion) + ")" +
           (validating_ ? ", with VK_LAYER_KHRONOS_validation" : "");
  }

  const VkPhysicalDeviceProperties& properties() const { return properties_; }

  // Long enough for a brute-force shader on a 2-core CPU device; a hung one still ends the test.
  double timeout_seconds() const { return timeout_seconds_; }
  void set_timeout_seconds(double seconds) { timeout_seconds_ = seconds; }

  // Seconds the last run spent in vkCreateComputePipelines and from submit to the fence, for
  // tests that report their cost (lavapipe compiles the shader in the second, see above).
  double last_pipeline_seconds() const { return last_pipeline_seconds_; }
  double last_dispatch_seconds() const { return last_dispatch_seconds_; }

  void run(const std::vector<std::uint32_t>& spirv, std::vector<std::vector<std::uint32_t>>& buffers,
           std::uint32_t groups_x, const std::vector<std::uint32_t>& push_constants = {}) {
    using detail::check;
    using detail::fail;
    using detail::owned;
    if (wedged_) {
      fail("the context is unusable: an earlier run timed out");
    }
    validation_errors_.clear();
    const VkPhysicalDeviceLimits& limits = properties_.limits;
    if (spirv.empty() || spirv[0] != detail::spirv_magic) {
      fail("run: the code is not SPIR-V (no magic number)");
    }
    const std::size_t push_bytes = push_constants.size() * sizeof(std::uint32_t);
    if (push_bytes > detail::max_push_constant_bytes || push_bytes > limits.maxPushConstantsSize) {
      fail("run: " + std::to_string(push_bytes) + " bytes of push constants; at most " +
           std::to_string(std::min<std::size_t>(detail::max_push_constant_bytes, limits.maxPushConstantsSize)));
    }
    if (buffers.size() > limits.maxPerStageDescriptorStorageBuffers) {
      fail("run: " + std::to_string(buffers.size()) + " storage buffers; the device binds at most " +
           std::to_string(limits.maxPerStageDescriptorStorageBuffers));
    }
    if (groups_x > limits.maxComputeWorkGroupCount[0]) {
      fail("run: " + std::to_string(groups_x) + " work groups; the device dispatches at most " +
           std::to_string(limits.maxComputeWorkGroupCount[0]));
    }
    for (std::size_t i = 0; i < buffers.size(); ++i) {
      if (buffers[i].size() * sizeof(std::uint32_t) > limits.maxStorageBufferRange) {
        fail("run: buffer " + std::to_string(i) + " has " + std::to_string(buffers[i].size() * 4) +
             " bytes; maxStorageBufferRange is " + std::to_string(limits.maxStorageBufferRange));
      }
    }
    const auto binding_count = static_cast<std::uint32_t>(buffers.size());
    detail::check_interface(spirv, binding_count, push_bytes);
    const VkDevice device = device_;

    owned<VkShaderModule> module(device, vkDestroyShaderModule);
    VkShaderModuleCreateInfo module_info{};
    module_info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    module_info.codeSize = spirv.size() * sizeof(std::uint32_t);
    module_info.pCode = spirv.data();
    check(vkCreateShaderModule(device, &module_info, nullptr, module.out()), "vkCreateShaderModule");

    std::vector<VkDescriptorSetLayoutBinding> bindings(buffers.size());
    for (std::uint32_t i = 0; i < binding_count; ++i) {
      bindings[i].binding = i;
      bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      bindings[i].descriptorCount = 1;
      bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    owned<VkDescriptorSetLayout> set_layout(device, vkDestroyDescriptorSetLayout);
    VkDescriptorSetLayoutCreateInfo set_layout_info{};
    set_layout_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    set_layout_info.bindingCount = binding_count;
    set_layout_info.pBindings = bindings.data();
    check(vkCreateDescriptorSetLayout(device, &set_layout_info, nullptr, set_layout.out()),
          "vkCreateDescriptorSetLayout");

    // A range only where there are constants: a zero-size range is invalid, and a shader without
    // a push-constant block runs with none.
    VkPushConstantRange push_range{};
    push_range.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    push_range.offset = 0;
    push_range.size = static_cast<std::uint32_t>(push_bytes);
    owned<VkPipelineLayout> pipeline_layout(device, vkDestroyPipelineLayout);
    VkPipelineLayoutCreateInfo pipeline_layout_info{};
    pipeline_layout_info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    pipeline_layout_info.setLayoutCount = 1;
    pipeline_layout_info.pSetLayouts = set_layout.out();
    pipeline_layout_info.pushConstantRangeCount = push_bytes > 0 ? 1u : 0u;
    pipeline_layout_info.pPushConstantRanges = &push_range;
    check(vkCreatePipelineLayout(device, &pipeline_layout_info, nullptr, pipeline_layout.out()),
          "vkCreatePipelineLayout");

    owned<VkPipeline> pipeline(device, vkDestroyPipeline);
    VkComputePipelineCreateInfo pipeline_info{};
    pipeline_info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    pipeline_info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    pipeline_info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipeline_info.stage.module = module.get();
    pipeline_info.stage.pName = "main";
    pipeline_info.layout = pipeline_layout.get();
    const auto pipeline_start = std::chrono::steady_clock::now();
    check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, pipeline.out()),
          "vkCreateComputePipelines");
    last_pipeline_seconds_ = seconds_since(pipeline_start);

    // One buffer and one allocation each: a test binds a handful, far below any allocation limit,
    // and no buffer then needs an offset aligned to minStorageBufferOffsetAlignment.
    std::vector<owned<VkBuffer>> device_buffers;
    std::vector<owned<VkDeviceMemory>> memories;
    std::vector<void*> mapped(buffers.size(), nullptr);
    device_buffers.reserve(buffers.size());
    memories.reserve(buffers.size());
    for (std::size_t i = 0; i < buffers.size(); ++i) {
      const std::size_t bytes = buffers[i].size() * sizeof(std::uint32_t);
      device_buffers.emplace_back(device, vkDestroyBuffer);
      VkBufferCreateInfo buffer_info{};
      buffer_info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
      buffer_info.size = std::max<std::size_t>(bytes, 4);  // a zero-size buffer is invalid
      buffer_info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
      buffer_info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
      check(vkCreateBuffer(device, &buffer_info, nullptr, device_buffers.back().out()), "vkCreateBuffer");

      VkMemoryRequirements requirements{};
      vkGetBufferMemoryRequirements(device, device_buffers.back().get(), &requirements);
      memories.emplace_back(device, vkFreeMemory);
      VkMemoryAllocateInfo allocate_info{};
      allocate_info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
      allocate_info.allocationSize = requirements.size;
      allocate_info.memoryTypeIndex = host_coherent_type(requirements.memoryTypeBits);
      check(vkAllocateMemory(device, &allocate_info, nullptr, memories.back().out()), "vkAllocateMemory");
      check(vkBindBufferMemory(device, device_buffers.back().get(), memories.back().get(), 0),
            "vkBindBufferMemory");
      // Mapped until vkFreeMemory, which unmaps; coherent, so no flush or invalidate.
      check(vkMapMemory(device, memories.back().get(), 0, VK_WHOLE_SIZE, 0, &mapped[i]), "vkMapMemory");
      std::memset(mapped[i], 0, static_cast<std::size_t>(requirements.size));
      if (bytes > 0) {
        std::memcpy(mapped[i], buffers[i].data(), bytes);
      }
    }

    // No pool without descriptors: a pool of no sizes is invalid, and the empty set is not bound.
    owned<VkDescriptorPool> descriptor_pool(device, vkDestroyDescriptorPool);
    VkDescriptorSet descriptor_set = VK_NULL_HANDLE;  // freed with its pool
    if (binding_count > 0) {
      VkDescriptorPoolSize pool_size{};
      pool_size.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      pool_size.descriptorCount = binding_count;
      VkDescriptorPoolCreateInfo pool_info{};
      pool_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
      pool_info.maxSets = 1;
      pool_info.poolSizeCount = 1;
      pool_info.pPoolSizes = &pool_size;
      check(vkCreateDescriptorPool(device, &pool_info, nullptr, descriptor_pool.out()), "vkCreateDescriptorPool");

      VkDescriptorSetAllocateInfo set_info{};
      set_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
      set_info.descriptorPool = descriptor_pool.get();
      set_info.descriptorSetCount = 1;
      set_info.pSetLayouts = set_layout.out();
      check(vkAllocateDescriptorSets(device, &set_info, &descriptor_set), "vkAllocateDescriptorSets");

      std::vector<VkDescriptorBufferInfo> buffer_infos(buffers.size());
      std::vector<VkWriteDescriptorSet> writes(buffers.size());
      for (std::uint32_t i = 0; i < binding_count; ++i) {
        buffer_infos[i].buffer = device_buffers[i].get();
        buffer_infos[i].offset = 0;
        buffer_infos[i].range = VK_WHOLE_SIZE;
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstSet = descriptor_set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[i].pBufferInfo = &buffer_infos[i];
      }
      vkUpdateDescriptorSets(device, binding_count, writes.data(), 0, nullptr);
    }

    owned<VkCommandPool> command_pool(device, vkDestroyCommandPool);  // frees its command buffer
    VkCommandPoolCreateInfo command_pool_info{};
    command_pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    command_pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    command_pool_info.queueFamilyIndex = queue_family_;
    check(vkCreateCommandPool(device, &command_pool_info, nullptr, command_pool.out()), "vkCreateCommandPool");

    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkCommandBufferAllocateInfo commands_info{};
    commands_info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    commands_info.commandPool = command_pool.get();
    commands_info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    commands_info.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(device, &commands_info, &commands), "vkAllocateCommandBuffers");

    VkCommandBufferBeginInfo begin_info{};
    begin_info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin_info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(commands, &begin_info), "vkBeginCommandBuffer");
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.get());
    if (descriptor_set != VK_NULL_HANDLE) {
      vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout.get(), 0, 1,
                              &descriptor_set, 0, nullptr);
    }
    if (push_bytes > 0) {
      vkCmdPushConstants(commands, pipeline_layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                         static_cast<std::uint32_t>(push_bytes), push_constants.data());
    }
    vkCmdDispatch(commands, groups_x, 1, 1);
    // The fence makes the shader's writes available, not visible to the host: coherent memory
    // still needs this barrier before the host reads (the submission itself covers the uploads).
    VkMemoryBarrier to_host{};
    to_host.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    to_host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &to_host, 0, nullptr, 0, nullptr);
    check(vkEndCommandBuffer(commands), "vkEndCommandBuffer");

    owned<VkFence> fence(device, vkDestroyFence);
    VkFenceCreateInfo fence_info{};
    fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    check(vkCreateFence(device, &fence_info, nullptr, fence.out()), "vkCreateFence");

    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    const auto dispatch_start = std::chrono::steady_clock::now();
    check(vkQueueSubmit(queue_, 1, &submit, fence.get()), "vkQueueSubmit");
    const auto timeout_ns = static_cast<std::uint64_t>(std::max(0.0, timeout_seconds_) * 1e9);
    const VkResult waited = vkWaitForFences(device, 1, fence.out(), VK_TRUE, timeout_ns);
    if (waited != VK_SUCCESS) {
      if (waited == VK_TIMEOUT) {
        // Everything the submission uses may still be in use: leak it (see the contract).
        wedged_ = true;
        module.release();
        set_layout.release();
        pipeline_layout.release();
        pipeline.release();
        for (auto& b : device_buffers) b.release();
        for (auto& m : memories) m.release();
        descriptor_pool.release();
        command_pool.release();
        fence.release();
        std::ostringstream message;
        message << "vkWaitForFences timed out (VK_TIMEOUT) after " << timeout_seconds_
                << " s; the context is now unusable";
        fail(message.str());
      }
      fail("vkWaitForFences", waited);
    }
    last_dispatch_seconds_ = seconds_since(dispatch_start);

    for (std::size_t i = 0; i < buffers.size(); ++i) {
      if (!buffers[i].empty()) {
        std::memcpy(buffers[i].data(), mapped[i], buffers[i].size() * sizeof(std::uint32_t));
      }
    }
    if (!validation_errors_.empty()) {
      std::string all = "VK_LAYER_KHRONOS_validation reported " + std::to_string(validation_errors_.size()) +
                        " error(s) during the run:";
      for (const std::string& message : validation_errors_) {
        all += "\n  " + message;
      }
      validation_errors_.clear();
      fail(all);
    }
  }

 private:
  friend std::unique_ptr<context> open(std::string& why_not);
  context() = default;

  static double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  std::uint32_t host_coherent_type(std::uint32_t allowed) const {
    const VkMemoryPropertyFlags wanted = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
      if ((allowed & (1u << i)) != 0 && (memory_.memoryTypes[i].propertyFlags & wanted) == wanted) {
        return i;
      }
    }
    detail::fail("no HOST_VISIBLE | HOST_COHERENT memory type for a storage buffer on " + device_name() +
                 " (this runner maps buffers directly and does not stage them)");
  }

  static VKAPI_ATTR VkBool32 VKAPI_CALL on_validation(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                      VkDebugUtilsMessageTypeFlagsEXT,
                                                      const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                      void* self) {
    const char* message = data != nullptr && data->pMessage != nullptr ? data->pMessage : "(no message)";
    std::cerr << "[vulkan validation] " << message << '\n';
    if ((severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0) {
      static_cast<context*>(self)->validation_errors_.emplace_back(message);
    }
    return VK_FALSE;
  }

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  VkDevice device_ = VK_NULL_HANDLE;
  std::uint32_t queue_family_ = 0;
  VkQueue queue_ = VK_NULL_HANDLE;
  bool validating_ = false;
  bool wedged_ = false;
  double timeout_seconds_ = 300.0;
  double last_pipeline_seconds_ = 0.0;
  double last_dispatch_seconds_ = 0.0;
  std::vector<std::string> validation_errors_;
};

inline std::unique_ptr<context> open(std::string& why_not) {
  why_not.clear();
  std::unique_ptr<context> made(new context());  // its destructor undoes a partial open
  auto refuse = [&](std::string why) {
    why_not = std::move(why);
    return std::unique_ptr<context>();
  };
  auto refuse_call = [&](const char* call, VkResult result) {
    return refuse(std::string(call) + " failed: " + result_name(result) + " (" + std::to_string(result) + ")");
  };

  // vkEnumerateInstanceVersion exists from loader 1.1 on: looked up, not linked, so that a 1.0
  // loader is a reason to skip rather than a missing symbol.
  auto enumerate_version =
      reinterpret_cast<PFN_vkEnumerateInstanceVersion>(vkGetInstanceProcAddr(nullptr, "vkEnumerateInstanceVersion"));
  std::uint32_t loader_version = VK_API_VERSION_1_0;
  if (enumerate_version == nullptr || enumerate_version(&loader_version) != VK_SUCCESS ||
      loader_version < VK_API_VERSION_1_1) {
    return refuse("the Vulkan loader is older than 1.1 (SPIR-V 1.3, --target-env vulkan1.1, needs 1.1)");
  }

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  const char* validation_layer = "VK_LAYER_KHRONOS_validation";
  if (detail::env_is("LTC_VULKAN_VALIDATE", "1")) {
    if (detail::has_layer(validation_layer)) {
      layers.push_back(validation_layer);
      made->validating_ = true;
      if (detail::has_instance_extension(validation_layer, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) ||
          detail::has_instance_extension(nullptr, VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) {
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
      }
    } else {
      std::cerr << "vulkan: LTC_VULKAN_VALIDATE=1 but " << validation_layer
                << " is not installed (Debian: vulkan-validationlayers); running without it\n";
    }
  }
  VkInstanceCreateFlags instance_flags = 0;
#ifdef VK_KHR_portability_enumeration
  // MoltenVK's devices are listed only to an instance that asks for portability devices.
  if (detail::has_instance_extension(nullptr, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
    extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
    instance_flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
  }
#endif

  VkApplicationInfo application{};
  application.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  application.pApplicationName = "ltc tests";
  application.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo instance_info{};
  instance_info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  instance_info.flags = instance_flags;
  instance_info.pApplicationInfo = &application;
  instance_info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  instance_info.ppEnabledLayerNames = layers.data();
  instance_info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  instance_info.ppEnabledExtensionNames = extensions.data();
  // The messenger of pNext also reports what vkCreateInstance itself finds.
  VkDebugUtilsMessengerCreateInfoEXT messenger_info{};
  messenger_info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  messenger_info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = &context::on_validation;
  messenger_info.pUserData = made.get();
  const bool debug_utils = std::find_if(extensions.begin(), extensions.end(), [](const char* e) {
                             return std::strcmp(e, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) == 0;
                           }) != extensions.end();
  if (debug_utils) {
    instance_info.pNext = &messenger_info;
  }
  const VkResult created = vkCreateInstance(&instance_info, nullptr, &made->instance_);
  if (created != VK_SUCCESS) {
    made->instance_ = VK_NULL_HANDLE;
    if (created == VK_ERROR_INCOMPATIBLE_DRIVER) {
      return refuse("vkCreateInstance: no Vulkan 1.1 driver (VK_ERROR_INCOMPATIBLE_DRIVER; is an ICD such as "
                    "mesa-vulkan-drivers installed?)");
    }
    return refuse_call("vkCreateInstance", created);
  }
  if (debug_utils) {
    auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(made->instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (create_messenger != nullptr &&
        create_messenger(made->instance_, &messenger_info, nullptr, &made->messenger_) != VK_SUCCESS) {
      made->messenger_ = VK_NULL_HANDLE;
    }
  }

  std::uint32_t device_count = 0;
  VkResult listed = vkEnumeratePhysicalDevices(made->instance_, &device_count, nullptr);
  if (listed != VK_SUCCESS) {
    return refuse_call("vkEnumeratePhysicalDevices", listed);
  }
  std::vector<VkPhysicalDevice> devices(device_count);
  listed = vkEnumeratePhysicalDevices(made->instance_, &device_count, devices.data());
  if (listed != VK_SUCCESS && listed != VK_INCOMPLETE) {
    return refuse_call("vkEnumeratePhysicalDevices", listed);
  }
  devices.resize(device_count);
  if (devices.empty()) {
    return refuse("no Vulkan physical device (no driver lists one)");
  }
  std::string rejected;
  for (VkPhysicalDevice candidate : devices) {
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(candidate, &properties);
    if (properties.apiVersion < VK_API_VERSION_1_1) {
      rejected += std::string(rejected.empty() ? "" : "; ") + properties.deviceName + ": Vulkan " +
                  detail::version_string(properties.apiVersion) + " < 1.1";
      continue;
    }
    std::uint32_t family_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &family_count, nullptr);
    std::vector<VkQueueFamilyProperties> families(family_count);
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &family_count, families.data());
    std::uint32_t family = 0;
    while (family < family_count &&
           ((families[family].queueFlags & VK_QUEUE_COMPUTE_BIT) == 0 || families[family].queueCount == 0)) {
      ++family;
    }
    if (family == family_count) {
      rejected += std::string(rejected.empty() ? "" : "; ") + properties.deviceName + ": no compute queue";
      continue;
    }
    made->physical_ = candidate;
    made->properties_ = properties;
    made->queue_family_ = family;
    break;
  }
  if (made->physical_ == VK_NULL_HANDLE) {
    return refuse("no Vulkan 1.1 device with a compute queue (" + rejected + ")");
  }
  vkGetPhysicalDeviceMemoryProperties(made->physical_, &made->memory_);

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{};
  queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queue_info.queueFamilyIndex = made->queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  std::vector<const char*> device_extensions;
  // A portability device must be created with the extension that says what it lacks.
  if (detail::has_device_extension(made->physical_, "VK_KHR_portability_subset")) {
    device_extensions.push_back("VK_KHR_portability_subset");
  }
  VkDeviceCreateInfo device_info{};
  device_info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  device_info.enabledExtensionCount = static_cast<std::uint32_t>(device_extensions.size());
  device_info.ppEnabledExtensionNames = device_extensions.data();
  const VkResult device_created = vkCreateDevice(made->physical_, &device_info, nullptr, &made->device_);
  if (device_created != VK_SUCCESS) {
    made->device_ = VK_NULL_HANDLE;
    return refuse_call(("vkCreateDevice on " + made->device_name()).c_str(), device_created);
  }
  vkGetDeviceQueue(made->device_, made->queue_family_, 0, &made->queue_);
  return made;
}

inline std::vector<std::uint32_t> read_spirv(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    detail::fail("read_spirv: cannot open " + path);
  }
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (file.bad()) {
    detail::fail("read_spirv: cannot read " + path);
  }
  if (bytes.empty() || bytes.size() % sizeof(std::uint32_t) != 0) {
    detail::fail("read_spirv: " + path + " has " + std::to_string(bytes.size()) +
                 " bytes, not a positive multiple of 4: not SPIR-V");
  }
  std::vector<std::uint32_t> words(bytes.size() / sizeof(std::uint32_t));
  std::memcpy(words.data(), bytes.data(), bytes.size());
  if (words[0] != detail::spirv_magic) {
    detail::fail("read_spirv: " + path + " does not start with SPIR-V's magic number (0x07230203)");
  }
  return words;
}

}  // namespace ltc_test::vulkan
