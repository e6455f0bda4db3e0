#pragma once
// Pipelines built from embedded SPIR-V. Every pass binds its per-pass resources as a push
// descriptor set (set 0) so passes need no descriptor pools; mesh passes add the material
// texture set (set 1). Descriptions are plain structs with the defaults most passes want.
#include <vulkan/vulkan.h>

#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace lll {

class Context;

struct ShaderInterface;

// Specialization constant values by constant_id.
using SpecializationConstants = std::map<uint32_t, uint32_t>;

class PipelineLayout {
 public:
  PipelineLayout() = default;
  // Set 0 (push descriptors) and the push constants as `shaders` declare them (SPIR-V reflection,
  // gpu/reflection.h; `constants` sizes arrays sized by specialization constants), then
  // `extraSets` as sets 1, 2, ... (not owned).
  PipelineLayout(Context& context, std::initializer_list<std::string_view> shaders,
                 std::vector<VkDescriptorSetLayout> extraSets = {},
                 const SpecializationConstants& constants = {});
  ~PipelineLayout();
  PipelineLayout(PipelineLayout&& other) noexcept;
  PipelineLayout& operator=(PipelineLayout&& other) noexcept;

  VkPipelineLayout handle() const { return layout_; }
  // The type of `binding` in set 0, VK_DESCRIPTOR_TYPE_MAX_ENUM where set 0 has none (a reflected
  // layout has only the bindings its shaders use).
  VkDescriptorType pushBindingType(uint32_t binding) const;

 private:
  void release();
  Context* context_ = nullptr;
  VkDescriptorSetLayout pushSet_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  std::vector<std::pair<uint32_t, VkDescriptorType>> pushBindings_;  // set 0's, by binding
};

enum class BlendMode { None, Additive, Alpha };

enum class VertexInput {
  Mesh,               // lll::Vertex (position, normal, uv) at binding 0, gpu::MeshInstance per instance at 1
  Vertices,           // lll::Vertex at binding 0 only (light volume shells)
  Position,           // a bare vec3 position at binding 0 (light volumes)
  PositionInstanced,  // a bare vec3 position at 0, gpu::MeshInstance's model per instance at 1
  None,               // no vertex buffer: the shader makes its own positions
};

struct GraphicsPipelineDesc {
  std::string vertexShader;    // path under shaders/, e.g. "common/mesh.vert"
  std::string fragmentShader;  // empty for depth-only passes
  VertexInput vertexInput = VertexInput::Mesh;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkCullModeFlags cullMode = VK_CULL_MODE_BACK_BIT;
  bool depthTest = true;
  bool depthWrite = true;
  VkCompareOp depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL;  // reverse-Z
  BlendMode blend = BlendMode::None;
  std::vector<VkFormat> colorFormats;
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  std::vector<uint32_t> specialization;  // constant_id 0, 1, ... in order
  SpecializationConstants constants;     // more by constant_id (these win over `specialization`)
  // Light volumes: clamp depth instead of clipping at the near and far planes, so a volume's back
  // faces beyond the far plane still cover the pixels they bound (needs the depthClamp feature).
  bool depthClamp = false;
  // Stencil volumes: the depth-stencil format's stencil aspect, the per-face stencil ops, and
  // whether colour attachments are written at all (a stencil-marking pass leaves them untouched).
  VkFormat stencilFormat = VK_FORMAT_UNDEFINED;
  bool stencilTest = false;
  VkStencilOpState stencilFront{};
  VkStencilOpState stencilBack{};
  bool colorWrite = true;
};

class Pipeline {
 public:
  Pipeline() = default;
  Pipeline(Context& context, const PipelineLayout& layout, const GraphicsPipelineDesc& desc);
  Pipeline(Context& context, const PipelineLayout& layout, const std::string& computeShader,
           const std::vector<uint32_t>& specialization = {});
  Pipeline(Context& context, const PipelineLayout& layout, const std::string& computeShader,
           const SpecializationConstants& constants);
  ~Pipeline();
  Pipeline(Pipeline&& other) noexcept;
  Pipeline& operator=(Pipeline&& other) noexcept;

  VkPipeline handle() const { return pipeline_; }
  VkPipelineBindPoint bindPoint() const { return bindPoint_; }
  // Binds the pipeline and, for graphics, sets its cull mode (cull mode is dynamic state so the
  // scene can switch it per material).
  void bind(VkCommandBuffer cmd) const;
  explicit operator bool() const { return pipeline_ != VK_NULL_HANDLE; }

 private:
  void release();
  Context* context_ = nullptr;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkPipelineBindPoint bindPoint_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
  VkCullModeFlags cullMode_ = VK_CULL_MODE_NONE;
};

// Writes for one push-descriptor update, built fluently and recorded with push().
// The descriptor types come from the layout the writes are pushed to, which has them from the
// shaders (reflection): a write names a binding and what to bind, never the GLSL's type again.
class DescriptorWriter {
 public:
  DescriptorWriter& storage(uint32_t binding, VkBuffer buffer, VkDeviceSize offset = 0,
                            VkDeviceSize range = VK_WHOLE_SIZE);
  // A sampled or storage image, or with `sampler` a combined image sampler.
  DescriptorWriter& image(uint32_t binding, VkImageView view, VkImageLayout layout,
                          VkSampler sampler = VK_NULL_HANDLE);
  // Pushes the writes `layout`'s set 0 has a binding for, typed as it declares them, and drops the
  // others: passes share writers (frame, lists, surfaces) while each reflected layout has only what
  // its shaders use.
  void push(Context& context, VkCommandBuffer cmd, VkPipelineBindPoint bindPoint,
            const PipelineLayout& layout);

 private:
  struct Entry {
    uint32_t binding;
    VkDescriptorBufferInfo bufferInfo;
    VkDescriptorImageInfo imageInfo;
    bool isImage;
  };
  std::vector<Entry> entries_;
};

// Something whose resources the passes after it read through their set 0 (the sun's and the local
// lights' shadows): it adds its writes to a pass's, so that the frame's shared code binds it
// without knowing what it is.
class DescriptorSource {
 public:
  virtual void bind(DescriptorWriter& writer) const = 0;

 protected:
  ~DescriptorSource() = default;
};

}  // namespace lll
