#pragma once
// The scene on the GPU: one vertex and index buffer, the material and light arrays, textures with
// mipmaps, one descriptor set of textures per material (set 1 of every mesh pass), and the draw
// lists every technique shares (opaque + mask first, blended afterwards sorted back to front).
#include <vulkan/vulkan.h>

#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "scene/scene.h"

namespace lll {

class Context;

struct DrawItem {
  uint32_t instance;
  uint32_t firstIndex;
  uint32_t indexCount;
  uint32_t vertexOffset;
  uint32_t material;
  glm::vec3 center;  // world-space centre, for back-to-front sorting of blended draws
};

enum class DrawFilter { OpaqueOnly, MaskOnly, Opaque, Blend, All };

class GpuScene {
 public:
  GpuScene(Context& context, const Scene& scene);
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  const Scene& scene() const { return scene_; }
  VkDescriptorSetLayout materialSetLayout() const { return materialSetLayout_; }
  const Buffer& materialBuffer() const { return materials_; }
  const Buffer& lightBuffer() const { return lights_; }
  uint32_t lightCount() const { return lightCount_; }
  // Replaces the light array (e.g. lights animated by the CPU); grows the buffer when needed.
  void uploadLights(const std::vector<Light>& lights);

  // Draws the filtered primitives with the given pipeline already bound: binds geometry, material
  // sets and per-draw constants. `materialCulling` sets the cull mode per material (double-sided
  // materials are not culled); otherwise the bound pipeline's cull mode is kept.
  // `eye` orders blended draws back to front.
  void draw(VkCommandBuffer cmd, VkPipelineLayout layout, DrawFilter filter, const glm::vec3& eye,
            bool materialCulling = true) const;
  bool hasBlendDraws() const;

 private:
  void uploadGeometry();
  void uploadMaterials();
  void uploadTextures();
  void createMaterialSets();
  bool matches(const DrawItem& item, DrawFilter filter) const;

  Context& context_;
  const Scene& scene_;
  Buffer vertices_;
  Buffer indices_;
  Buffer materials_;
  Buffer lights_;
  uint32_t lightCount_ = 0;
  std::vector<Image> textures_;  // scene textures, then neutral white, neutral normal, black
  std::vector<DrawItem> draws_;
  VkSampler sampler_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout materialSetLayout_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> materialSets_;
};

}  // namespace lll
