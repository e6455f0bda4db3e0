#include "gpu/pipeline.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/vertex.h"
#include "gpu/context.h"
#include "gpu/reflection.h"
#include "gpu/shader_registry.h"
#include "gpu/vk_check.h"
#include "shared/gpu_types.h"

namespace lll {

std::span<const uint32_t> shaderCode(std::string_view path) {
  for (const EmbeddedShader& shader : embeddedShaders()) {
    if (shader.path == path) return {shader.words, shader.wordCount};
  }
  throw std::logic_error(fmt::format("shader '{}' is not embedded in this binary", path));
}

namespace {

class ShaderModule {
 public:
  ShaderModule(Context& context, const std::string& path) : device_(context.device()) {
    const auto code = shaderCode(path);
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = code.size_bytes();
    info.pCode = code.data();
    VK_CHECK(vkCreateShaderModule(device_, &info, nullptr, &module_));
  }
  ~ShaderModule() { vkDestroyShaderModule(device_, module_, nullptr); }
  ShaderModule(const ShaderModule&) = delete;
  ShaderModule& operator=(const ShaderModule&) = delete;
  VkShaderModule handle() const { return module_; }

 private:
  VkDevice device_;
  VkShaderModule module_ = VK_NULL_HANDLE;
};

struct Specialization {
  std::vector<VkSpecializationMapEntry> entries;
  std::vector<uint32_t> values;
  VkSpecializationInfo info{};
  explicit Specialization(const std::vector<uint32_t>& inOrder, const SpecializationConstants& byId = {}) {
    SpecializationConstants all = byId;
    for (uint32_t i = 0; i < inOrder.size(); ++i) all.emplace(i, inOrder[i]);
    for (const auto& [id, value] : all) {
      entries.push_back({id, uint32_t(values.size() * 4), 4});
      values.push_back(value);
    }
    info.mapEntryCount = uint32_t(entries.size());
    info.pMapEntries = entries.data();
    info.dataSize = values.size() * 4;
    info.pData = values.data();
  }
  const VkSpecializationInfo* get() const { return entries.empty() ? nullptr : &info; }
  SpecializationConstants byId() const {
    SpecializationConstants out;
    for (size_t i = 0; i < entries.size(); ++i) out[entries[i].constantID] = values[i];
    return out;
  }
};

VkDescriptorSetLayout createPushSetLayout(Context& context,
                                          const std::vector<VkDescriptorSetLayoutBinding>& bindings) {
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  setInfo.bindingCount = uint32_t(bindings.size());
  setInfo.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(context.device(), &setInfo, nullptr, &layout));
  return layout;
}

VkPipelineLayout createLayout(Context& context, VkDescriptorSetLayout pushSet,
                              const std::vector<VkDescriptorSetLayout>& extraSets, uint32_t pushBytes,
                              VkShaderStageFlags pushStages) {
  std::vector<VkDescriptorSetLayout> sets{pushSet};
  sets.insert(sets.end(), extraSets.begin(), extraSets.end());
  VkPushConstantRange range{pushStages, 0, pushBytes};
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = uint32_t(sets.size());
  info.pSetLayouts = sets.data();
  info.pushConstantRangeCount = pushBytes ? 1 : 0;
  info.pPushConstantRanges = &range;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(context.device(), &info, nullptr, &layout));
  return layout;
}

}  // namespace

PipelineLayout::PipelineLayout(Context& context, std::initializer_list<std::string_view> shaders,
                               std::vector<VkDescriptorSetLayout> extraSets,
                               const SpecializationConstants& constants)
    : context_(&context) {
  std::vector<ShaderInterface> stages;
  for (std::string_view shader : shaders)
    stages.push_back(reflectShader(shaderCode(shader), std::string(shader), constants));
  const ShaderInterface merged = mergeInterfaces(stages);
  std::vector<VkDescriptorSetLayoutBinding> vkBindings;
  for (const ReflectedBinding& b : merged.set(0))
    vkBindings.push_back({b.binding, b.type, b.count, b.stages, nullptr});
  pushSet_ = createPushSetLayout(context, vkBindings);
  // Push constants for every stage of the pipeline, whichever declare them: the code that pushes
  // them (GpuScene::draw, for one) names the stages of a pass, not of each shader.
  layout_ = createLayout(context, pushSet_, extraSets, merged.pushConstantBytes,
                         merged.pushConstantBytes ? merged.stages : 0);
  for (const VkDescriptorSetLayoutBinding& b : vkBindings)
    pushBindings_.emplace_back(b.binding, b.descriptorType);
}

VkDescriptorType PipelineLayout::pushBindingType(uint32_t binding) const {
  for (const auto& [number, type] : pushBindings_)
    if (number == binding) return type;
  return VK_DESCRIPTOR_TYPE_MAX_ENUM;
}

PipelineLayout::~PipelineLayout() {
  release();
}

PipelineLayout::PipelineLayout(PipelineLayout&& other) noexcept {
  *this = std::move(other);
}

PipelineLayout& PipelineLayout::operator=(PipelineLayout&& other) noexcept {
  if (this != &other) {
    release();
    context_ = std::exchange(other.context_, nullptr);
    pushSet_ = std::exchange(other.pushSet_, VK_NULL_HANDLE);
    layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
    pushBindings_ = std::move(other.pushBindings_);
  }
  return *this;
}

void PipelineLayout::release() {
  if (!context_) return;
  vkDestroyPipelineLayout(context_->device(), layout_, nullptr);
  vkDestroyDescriptorSetLayout(context_->device(), pushSet_, nullptr);
  context_ = nullptr;
}

namespace {

// One line per executable of `pipeline` on stderr: "shader stats NAME {id: value, ...}: statistic
// value, ..." (Context::shaderStatistics).
void printShaderStatistics(Context& context, VkPipeline pipeline, const std::string& name,
                           const SpecializationConstants& constants) {
  VkPipelineInfoKHR info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
  info.pipeline = pipeline;
  uint32_t count = 0;
  context.getPipelineExecutableProperties(context.device(), &info, &count, nullptr);
  std::vector<VkPipelineExecutablePropertiesKHR> executables(
      count, VkPipelineExecutablePropertiesKHR{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
  context.getPipelineExecutableProperties(context.device(), &info, &count, executables.data());
  std::string specialization;
  for (const auto& [id, value] : constants)
    specialization += fmt::format("{}{}: {}", specialization.empty() ? "" : ", ", id, value);
  for (uint32_t e = 0; e < count; ++e) {
    VkPipelineExecutableInfoKHR executable{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
    executable.pipeline = pipeline;
    executable.executableIndex = e;
    uint32_t statistics = 0;
    context.getPipelineExecutableStatistics(context.device(), &executable, &statistics, nullptr);
    std::vector<VkPipelineExecutableStatisticKHR> values(
        statistics, VkPipelineExecutableStatisticKHR{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
    context.getPipelineExecutableStatistics(context.device(), &executable, &statistics, values.data());
    std::string line;
    for (const VkPipelineExecutableStatisticKHR& v : values) {
      std::string value;
      switch (v.format) {
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR:
          value = v.value.b32 ? "true" : "false";
          break;
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR:
          value = fmt::format("{}", v.value.i64);
          break;
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR:
          value = fmt::format("{}", v.value.u64);
          break;
        default:
          value = fmt::format("{}", v.value.f64);
          break;
      }
      line += fmt::format("{}{} {}", line.empty() ? "" : ", ", v.name, value);
    }
    fmt::print(stderr, "shader stats {} {{{}}} {}: {}\n", name, specialization, executables[e].name, line);
  }
}

}  // namespace

Pipeline::Pipeline(Context& context, const PipelineLayout& layout, const GraphicsPipelineDesc& desc)
    : context_(&context), bindPoint_(VK_PIPELINE_BIND_POINT_GRAPHICS), cullMode_(desc.cullMode) {
  ShaderModule vertex(context, desc.vertexShader);
  std::optional<ShaderModule> fragment;
  if (!desc.fragmentShader.empty()) fragment.emplace(context, desc.fragmentShader);
  const Specialization specialization(desc.specialization, desc.constants);
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  stages.push_back({VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0,
                    VK_SHADER_STAGE_VERTEX_BIT, vertex.handle(), "main", specialization.get()});
  if (fragment)
    stages.push_back({VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0,
                      VK_SHADER_STAGE_FRAGMENT_BIT, fragment->handle(), "main", specialization.get()});

  const VkVertexInputBindingDescription positionBinding{0, sizeof(float) * 3, VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription attributes[] = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
      {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, uv)},
      {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(Vertex, tangent)},
      {4, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, uv1)},
      {5, 0, VK_FORMAT_R16G16B16A16_SFLOAT, offsetof(Vertex, color)},
  };
  // Mesh passes add the frame's instances in draw order at binding 1, one gpu::MeshInstance per
  // instance: the model matrix at locations 8-11, the normal matrix at 12-14.
  const VkVertexInputBindingDescription meshBindings[] = {
      {0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX},
      {1, sizeof(gpu::MeshInstance), VK_VERTEX_INPUT_RATE_INSTANCE}};
  // The visibility pass: positions alone (GpuScene::positionBuffer) and the model matrices.
  const VkVertexInputBindingDescription positionInstancedBindings[] = {
      positionBinding, {1, sizeof(gpu::MeshInstance), VK_VERTEX_INPUT_RATE_INSTANCE}};
  const bool instanced =
      desc.vertexInput == VertexInput::Mesh || desc.vertexInput == VertexInput::PositionInstanced;
  std::vector<VkVertexInputAttributeDescription> used;
  if (desc.vertexInput == VertexInput::Position || desc.vertexInput == VertexInput::PositionInstanced)
    used.push_back({0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0});
  if (desc.vertexInput == VertexInput::Mesh || desc.vertexInput == VertexInput::Vertices)
    used.assign(std::begin(attributes), std::end(attributes));
  if (instanced) {
    for (uint32_t column = 0; column < 4; ++column)
      used.push_back({8 + column, 1, VK_FORMAT_R32G32B32A32_SFLOAT,
                      uint32_t(offsetof(gpu::MeshInstance, model) + 16 * column)});
  }
  if (desc.vertexInput == VertexInput::Mesh) {
    for (uint32_t column = 0; column < 3; ++column)
      used.push_back({12 + column, 1, VK_FORMAT_R32G32B32A32_SFLOAT,
                      uint32_t(offsetof(gpu::MeshInstance, normalMatrix) + 16 * column)});
  }
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  if (desc.vertexInput != VertexInput::None) {
    vertexInput.vertexBindingDescriptionCount = instanced ? 2 : 1;
    vertexInput.pVertexBindingDescriptions = desc.vertexInput == VertexInput::Position ? &positionBinding
                                             : desc.vertexInput == VertexInput::PositionInstanced
                                                 ? positionInstancedBindings
                                                 : meshBindings;
    vertexInput.vertexAttributeDescriptionCount = uint32_t(used.size());
    vertexInput.pVertexAttributeDescriptions = used.data();
  }
  VkPipelineInputAssemblyStateCreateInfo inputAssembly{
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  inputAssembly.topology = desc.topology;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = desc.cullMode;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  raster.depthClampEnable = desc.depthClamp;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = desc.depthTest;
  depth.depthWriteEnable = desc.depthWrite;
  depth.depthCompareOp = desc.depthCompare;
  depth.stencilTestEnable = desc.stencilTest;
  depth.front = desc.stencilFront;
  depth.back = desc.stencilBack;

  std::vector<VkPipelineColorBlendAttachmentState> blends(desc.colorFormats.size());
  for (auto& blend : blends) {
    if (desc.colorWrite)
      blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                             VK_COLOR_COMPONENT_A_BIT;
    if (desc.blend == BlendMode::Additive) {
      blend.blendEnable = VK_TRUE;
      blend.srcColorBlendFactor = blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
      blend.srcAlphaBlendFactor = blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    } else if (desc.blend == BlendMode::Alpha) {
      // Premultiplied alpha: shaders output colour * alpha, so additive glow and glass share a mode.
      blend.blendEnable = VK_TRUE;
      blend.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
      blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
      blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
      blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    }
  }
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = uint32_t(blends.size());
  blend.pAttachments = blends.data();
  const VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                          VK_DYNAMIC_STATE_CULL_MODE};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 3;
  dynamic.pDynamicStates = dynamicStates;
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = uint32_t(desc.colorFormats.size());
  rendering.pColorAttachmentFormats = desc.colorFormats.data();
  rendering.depthAttachmentFormat = desc.depthFormat;
  rendering.stencilAttachmentFormat = desc.stencilFormat;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
  info.stageCount = uint32_t(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &inputAssembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout.handle();
  VK_CHECK(vkCreateGraphicsPipelines(context.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_));
}

Pipeline::Pipeline(Context& context, const PipelineLayout& layout, const std::string& computeShader,
                   const std::vector<uint32_t>& specialization)
    : Pipeline(context, layout, computeShader, Specialization(specialization).byId()) {}

Pipeline::Pipeline(Context& context, const PipelineLayout& layout, const std::string& computeShader,
                   const SpecializationConstants& constants)
    : context_(&context), bindPoint_(VK_PIPELINE_BIND_POINT_COMPUTE) {
  ShaderModule module(context, computeShader);
  const Specialization spec({}, constants);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                nullptr,
                0,
                VK_SHADER_STAGE_COMPUTE_BIT,
                module.handle(),
                "main",
                spec.get()};
  info.layout = layout.handle();
  if (context.shaderStatistics()) info.flags |= VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR;
  VK_CHECK(vkCreateComputePipelines(context.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_));
  if (context.shaderStatistics()) printShaderStatistics(context, pipeline_, computeShader, constants);
}

Pipeline::~Pipeline() {
  release();
}

Pipeline::Pipeline(Pipeline&& other) noexcept {
  *this = std::move(other);
}

Pipeline& Pipeline::operator=(Pipeline&& other) noexcept {
  if (this != &other) {
    release();
    context_ = std::exchange(other.context_, nullptr);
    pipeline_ = std::exchange(other.pipeline_, VK_NULL_HANDLE);
    bindPoint_ = other.bindPoint_;
    cullMode_ = other.cullMode_;
  }
  return *this;
}

void Pipeline::release() {
  if (context_ && pipeline_) vkDestroyPipeline(context_->device(), pipeline_, nullptr);
  pipeline_ = VK_NULL_HANDLE;
  context_ = nullptr;
}

void Pipeline::bind(VkCommandBuffer cmd) const {
  vkCmdBindPipeline(cmd, bindPoint_, pipeline_);
  if (bindPoint_ == VK_PIPELINE_BIND_POINT_GRAPHICS) vkCmdSetCullMode(cmd, cullMode_);
}

DescriptorWriter& DescriptorWriter::storage(uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                                            VkDeviceSize range) {
  entries_.push_back({binding, {buffer, offset, range}, {}, false});
  return *this;
}

DescriptorWriter& DescriptorWriter::image(uint32_t binding, VkImageView view, VkImageLayout layout,
                                          VkSampler sampler) {
  entries_.push_back({binding, {}, {sampler, view, layout}, true});
  return *this;
}

void DescriptorWriter::push(Context& context, VkCommandBuffer cmd, VkPipelineBindPoint bindPoint,
                            const PipelineLayout& layout) {
  std::vector<VkWriteDescriptorSet> writes;
  for (const Entry& e : entries_) {
    const VkDescriptorType type = layout.pushBindingType(e.binding);
    if (type == VK_DESCRIPTOR_TYPE_MAX_ENUM) continue;
    const bool imageType = type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE ||
                           type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE ||
                           type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    if (imageType != e.isImage)
      throw std::logic_error(fmt::format("binding {}: the shaders declare {}, but {} was written to it",
                                         e.binding, imageType ? "an image" : "a buffer",
                                         e.isImage ? "an image" : "a buffer"));
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstBinding = e.binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    if (e.isImage)
      w.pImageInfo = &e.imageInfo;
    else
      w.pBufferInfo = &e.bufferInfo;
    writes.push_back(w);
  }
  context.cmdPushDescriptorSet(cmd, bindPoint, layout.handle(), 0, uint32_t(writes.size()), writes.data());
}

}  // namespace lll
