#include "gpu/reflection.h"

#include <fmt/format.h>
#include <spirv_cross/spirv_cross_c.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace lll {

namespace {

// spvc_context owns everything SPIRV-Cross allocates for one module.
using ContextHandle = std::unique_ptr<spvc_context_s, decltype(&spvc_context_destroy)>;

VkShaderStageFlags stageOf(SpvExecutionModel model) {
  switch (model) {
    case SpvExecutionModelVertex:
      return VK_SHADER_STAGE_VERTEX_BIT;
    case SpvExecutionModelFragment:
      return VK_SHADER_STAGE_FRAGMENT_BIT;
    case SpvExecutionModelGLCompute:
      return VK_SHADER_STAGE_COMPUTE_BIT;
    default:
      return 0;
  }
}

// The descriptor type of a resource SPIRV-Cross lists under `kind`; texel buffers are images of
// dimension Buffer.
VkDescriptorType descriptorType(spvc_resource_type kind, spvc_type type) {
  const bool texelBuffer =
      (kind == SPVC_RESOURCE_TYPE_STORAGE_IMAGE || kind == SPVC_RESOURCE_TYPE_SAMPLED_IMAGE ||
       kind == SPVC_RESOURCE_TYPE_SEPARATE_IMAGE) &&
      spvc_type_get_image_dimension(type) == SpvDimBuffer;
  switch (kind) {
    case SPVC_RESOURCE_TYPE_UNIFORM_BUFFER:
      return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case SPVC_RESOURCE_TYPE_STORAGE_BUFFER:
      return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case SPVC_RESOURCE_TYPE_STORAGE_IMAGE:
      return texelBuffer ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    case SPVC_RESOURCE_TYPE_SAMPLED_IMAGE:
      return texelBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                         : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    case SPVC_RESOURCE_TYPE_SEPARATE_IMAGE:
      return texelBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS:
      return VK_DESCRIPTOR_TYPE_SAMPLER;
    default:
      return VK_DESCRIPTOR_TYPE_MAX_ENUM;
  }
}

struct Reader {
  spvc_context context;
  spvc_compiler compiler;
  const std::string& name;
  const std::map<uint32_t, uint32_t>& specialization;

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(
        fmt::format("shader {}: {}: {}", name, what, spvc_context_get_last_error_string(context)));
  }

  // An array's element count: a literal, or a specialization constant's value.
  uint32_t arraySize(spvc_type type) const {
    if (spvc_type_get_num_array_dimensions(type) == 0) return 1;
    const SpvId size = spvc_type_get_array_dimension(type, 0);
    if (spvc_type_array_dimension_is_literal(type, 0)) return size;  // 0: a runtime array
    const uint32_t constantId = spvc_compiler_get_decoration(compiler, size, SpvDecorationSpecId);
    const auto given = specialization.find(constantId);
    if (given != specialization.end()) return given->second;
    return spvc_constant_get_scalar_u32(spvc_compiler_get_constant_handle(compiler, size), 0, 0);
  }

  void addResources(spvc_resources resources, spvc_resource_type kind, VkShaderStageFlags stage,
                    ShaderInterface& out) const {
    const spvc_reflected_resource* list = nullptr;
    size_t count = 0;
    if (spvc_resources_get_resource_list_for_type(resources, kind, &list, &count) != SPVC_SUCCESS)
      fail("cannot list its resources");
    for (size_t i = 0; i < count; ++i) {
      const spvc_type type = spvc_compiler_get_type_handle(compiler, list[i].type_id);
      ReflectedBinding b;
      b.set = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
      b.binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
      b.type = descriptorType(kind, type);
      b.count = arraySize(type);
      b.stages = stage;
      b.name = list[i].name ? list[i].name : "";
      if (b.type == VK_DESCRIPTOR_TYPE_MAX_ENUM)
        throw std::runtime_error(
            fmt::format("shader {}: binding {} ({}) has a type lll does not bind", name, b.binding, b.name));
      out.bindings.push_back(std::move(b));
    }
  }

  void addPushConstants(spvc_resources resources, VkShaderStageFlags stage, ShaderInterface& out) const {
    const spvc_reflected_resource* list = nullptr;
    size_t count = 0;
    spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_PUSH_CONSTANT, &list, &count);
    for (size_t i = 0; i < count; ++i) {
      size_t bytes = 0;
      if (spvc_compiler_get_declared_struct_size(
              compiler, spvc_compiler_get_type_handle(compiler, list[i].base_type_id), &bytes) !=
          SPVC_SUCCESS)
        fail("cannot size its push constants");
      out.pushConstantBytes = std::max(out.pushConstantBytes, uint32_t(bytes));
      out.pushConstantStages |= stage;
    }
  }
};

}  // namespace

std::vector<ReflectedBinding> ShaderInterface::set(uint32_t index) const {
  std::vector<ReflectedBinding> out;
  for (const ReflectedBinding& b : bindings)
    if (b.set == index) out.push_back(b);
  return out;
}

const ReflectedBinding* ShaderInterface::find(uint32_t setIndex, uint32_t binding) const {
  for (const ReflectedBinding& b : bindings)
    if (b.set == setIndex && b.binding == binding) return &b;
  return nullptr;
}

ShaderInterface reflectShader(std::span<const uint32_t> spirv, const std::string& name,
                              const std::map<uint32_t, uint32_t>& specialization) {
  spvc_context raw = nullptr;
  if (spvc_context_create(&raw) != SPVC_SUCCESS) throw std::runtime_error("SPIRV-Cross: no context");
  const ContextHandle context(raw, &spvc_context_destroy);
  Reader reader{raw, nullptr, name, specialization};
  spvc_parsed_ir ir = nullptr;
  if (spvc_context_parse_spirv(raw, spirv.data(), spirv.size(), &ir) != SPVC_SUCCESS)
    reader.fail("cannot parse");
  if (spvc_context_create_compiler(raw, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                   &reader.compiler) != SPVC_SUCCESS)
    reader.fail("cannot reflect");
  spvc_resources resources = nullptr;
  if (spvc_compiler_create_shader_resources(reader.compiler, &resources) != SPVC_SUCCESS)
    reader.fail("cannot list its resources");

  ShaderInterface out;
  out.stages = stageOf(spvc_compiler_get_execution_model(reader.compiler));
  if (out.stages == 0) throw std::runtime_error(fmt::format("shader {}: a stage lll does not use", name));
  for (spvc_resource_type kind : {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, SPVC_RESOURCE_TYPE_STORAGE_BUFFER,
                                  SPVC_RESOURCE_TYPE_STORAGE_IMAGE, SPVC_RESOURCE_TYPE_SAMPLED_IMAGE,
                                  SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS})
    reader.addResources(resources, kind, out.stages, out);
  reader.addPushConstants(resources, out.stages, out);
  std::sort(out.bindings.begin(), out.bindings.end(),
            [](const ReflectedBinding& a, const ReflectedBinding& b) {
              return a.set != b.set ? a.set < b.set : a.binding < b.binding;
            });
  return out;
}

ShaderInterface mergeInterfaces(const std::vector<ShaderInterface>& stages) {
  ShaderInterface merged;
  for (const ShaderInterface& stage : stages) {
    merged.stages |= stage.stages;
    merged.pushConstantBytes = std::max(merged.pushConstantBytes, stage.pushConstantBytes);
    merged.pushConstantStages |= stage.pushConstantStages;
    for (const ReflectedBinding& b : stage.bindings) {
      auto it = std::find_if(merged.bindings.begin(), merged.bindings.end(), [&](const ReflectedBinding& m) {
        return m.set == b.set && m.binding == b.binding;
      });
      if (it == merged.bindings.end()) {
        merged.bindings.push_back(b);
        continue;
      }
      if (it->type != b.type || it->count != b.count)
        throw std::logic_error(fmt::format("set {} binding {} is {} in one stage and {} in another", b.set,
                                           b.binding, it->name, b.name));
      it->stages |= b.stages;
    }
  }
  std::sort(merged.bindings.begin(), merged.bindings.end(),
            [](const ReflectedBinding& a, const ReflectedBinding& b) {
              return a.set != b.set ? a.set < b.set : a.binding < b.binding;
            });
  return merged;
}

}  // namespace lll
