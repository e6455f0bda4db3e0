#pragma once
// What a shader declares, read from its SPIR-V (SPIRV-Cross's C API, Debian's
// libspirv-cross-c-shared-dev): descriptor bindings, push constants, specialization constants.
// Pipeline layouts are built from this, so no C++ table repeats a binding number of the GLSL.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace lll {

struct ReflectedBinding {
  uint32_t set = 0;
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
  uint32_t count = 1;             // array size (after specialization)
  VkShaderStageFlags stages = 0;  // every stage that declares it
  std::string name;               // the GLSL block or variable name, for messages
  bool operator==(const ReflectedBinding&) const = default;
};

struct ShaderInterface {
  std::vector<ReflectedBinding> bindings;  // sorted by set, then binding
  uint32_t pushConstantBytes = 0;
  VkShaderStageFlags pushConstantStages = 0;
  VkShaderStageFlags stages = 0;

  // Every binding of `set`, in binding order.
  std::vector<ReflectedBinding> set(uint32_t index) const;
  const ReflectedBinding* find(uint32_t set, uint32_t binding) const;
};

// Reads one module. An array sized by a specialization constant takes the value `specialization`
// gives that constant (by constant_id), else the constant's default. Throws std::runtime_error
// naming `name` for SPIR-V SPIRV-Cross cannot parse, or a binding of a type lll does not use.
ShaderInterface reflectShader(std::span<const uint32_t> spirv, const std::string& name,
                              const std::map<uint32_t, uint32_t>& specialization = {});

// The interface of the stages of one pipeline together: bindings that several stages declare are
// merged (their stages or-ed); the same set and binding with different types or counts is a
// std::logic_error naming both stages, a bug in the shaders.
ShaderInterface mergeInterfaces(const std::vector<ShaderInterface>& stages);

}  // namespace lll
