#pragma once
// The scene on the GPU: one vertex and index buffer, the material and light arrays, textures with
// mipmaps, the instances (a transform and normal matrix each), one descriptor set per material
// (set 1 of every mesh pass: its textures), and the draw
// lists every technique shares (opaque + mask first, blended afterwards sorted back to front).
//
// Instancing: a draw covers one primitive of a mesh in every visible instance of that mesh, so
// the number of draws follows meshes x materials, not instances. Each frame prepareFrame() culls
// the instances against the view frustum and writes their transforms and normal matrices (computed
// once on the CPU) in draw order into vertex binding 1, read at instance rate: each mesh's visible
// instances for the opaque draws, then the (primitive, instance) pairs of blended draws sorted
// back to front. Instance-rate attributes rather than a storage buffer indexed by
// gl_InstanceIndex: lavapipe loads storage buffers lane by lane, which doubled vertex shading.
#include <vulkan/vulkan.h>

#include <array>
#include <string>
#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "scene/scene.h"
#include "shared/gpu_types.h"

namespace lll {

class Context;

// One primitive of one mesh: drawn once per visible instance of the mesh.
struct DrawItem {
  uint32_t mesh;
  uint32_t firstIndex;
  uint32_t indexCount;
  uint32_t vertexOffset;
  uint32_t material;
  glm::vec3 center;  // object-space centre, for back-to-front sorting of blended draws
};

enum class DrawFilter { OpaqueOnly, MaskOnly, Opaque, Blend, All };

// The light records the light buffer also offers as a uniform buffer (common/frame.glsl's binding
// 51): the buffer is at least this large.
constexpr VkDeviceSize kUniformLightRecordBytes = gpu::kUniformLightRecords * sizeof(gpu::GpuLight);

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
  // Writes the light array: at load, and again between frames when lights moved (the same lights,
  // same types: passes specialize on which light types the scene has, lightTypeConstants in
  // render/frame.h). Shadow views set in it by LocalShadows are cleared (Renderer::updateLights).
  void uploadLights(const std::vector<Light>& lights);
  uint32_t lightCount() const { return lightCount_; }
  // Where the block of VPLs at the end of the light array starts (lightCount() without VPLs), and
  // whether every VPL is in it (as --gi appends them): --vpl-interleave classes them by index.
  uint32_t firstTrailingVpl() const { return firstTrailingVpl_; }
  bool vplsTrail() const { return vplsTrail_; }
  // Whether local lights cast shadows this run (--shadows all): set by the renderer before any pass
  // specializes its light evaluation on it (lightTypeConstants, render/frame.h).
  bool shadowedLights() const { return shadowedLights_; }
  // Whether a material reads TEXCOORD_1 for one of its textures, and whether a vertex has a
  // colour other than white (glTF's COLOR_0): the visibility surface rebuild specializes on them
  // (VisibilityBuffer::surfaceConstants).
  bool secondTexCoords() const { return secondTexCoords_; }
  bool vertexColors() const { return vertexColors_; }
  // Whether a material's texture has a KHR_texture_transform other than the identity (the same
  // specialization).
  bool textureTransforms() const { return textureTransforms_; }
  void setShadowedLights(bool on) { shadowedLights_ = on; }

  // Geometry for passes that fetch it themselves: the visibility pass's position-only stream
  // (tightly packed vec3) and, for rebuilding surfaces in compute, every vertex (lll::Vertex) and
  // index.
  const Buffer& positionBuffer() const { return positions_; }
  const Buffer& vertexBuffer() const { return vertices_; }
  const Buffer& indexBuffer() const { return indices_; }
  // Every texture in one array (compute passes that shade any material: GpuMaterial::textures
  // indexes it), set 1 of those passes. Null handles when the device cannot bind that many
  // sampled images in one stage; textureTableProblem() then says why.
  VkDescriptorSetLayout textureTableLayout() const { return textureTableLayout_; }
  VkDescriptorSet textureTable() const { return textureTable_; }
  uint32_t textureCount() const { return uint32_t(textures_.size()); }
  const std::string& textureTableProblem() const { return textureTableProblem_; }

  // The scene's primitives (grouped by material) and, at the last prepareFrame(), where each
  // mesh's visible instances sit in the frame's instance buffer.
  const std::vector<DrawItem>& draws() const { return draws_; }
  bool isBlended(const DrawItem& item) const { return matches(item, DrawFilter::Blend); }
  uint32_t meshFirstInstance(uint32_t mesh) const { return meshFirst_[mesh]; }
  uint32_t meshVisibleInstances(uint32_t mesh) const { return meshVisible_[mesh]; }
  // How many instances each mesh has (the most a frame can draw of it).
  uint32_t meshInstanceCount(uint32_t mesh) const { return uint32_t(meshInstances_[mesh].size()); }
  const Buffer& frameInstances() const { return frameInstances_; }

  // Culls the instances against `viewProj`'s frustum and writes the draw order for the frame's
  // draws, blended ones sorted back to front from `eye`. Call once per frame before recording
  // (the previous frame's GPU work must be done: the instances are in host-visible memory).
  void prepareFrame(const glm::mat4& viewProj, const glm::vec3& eye);
  // Draws the filtered primitives, instanced, with the given pipeline already bound: binds
  // geometry, material sets and per-draw constants. `materialCulling` sets the cull mode per
  // material (double-sided materials are not culled); otherwise the bound pipeline's is kept.
  void draw(VkCommandBuffer cmd, VkPipelineLayout layout, DrawFilter filter,
            bool materialCulling = true) const;
  bool hasBlendDraws() const;
  // Binds `material`'s textures as set 1 of a graphics pipeline `layout`.
  void bindMaterialSet(VkCommandBuffer cmd, VkPipelineLayout layout, uint32_t material) const;
  // The instanced draws draw() records for `filter` this frame: one per primitive with a visible
  // instance (per run of one primitive, for blended draws sorted back to front).
  uint32_t drawCount(DrawFilter filter) const { return uint32_t(runs(filter).size()); }
  // Instances inside the frustum at the last prepareFrame().
  uint32_t visibleInstances() const { return visibleInstances_; }

 private:
  void uploadGeometry();
  void uploadInstances();
  void uploadMaterials();
  void uploadTextures();
  void createMaterialSets();
  void createTextureTable();
  bool matches(const DrawItem& item, DrawFilter filter) const;
  // Where a material's base colour, metallic-roughness, normal, emissive and occlusion textures sit
  // in textures_ (neutral textures where it has none).
  using TextureSlots = std::array<uint32_t, 5>;
  TextureSlots textureSlots(const Material& material) const;
  void bindMaterial(VkCommandBuffer cmd, VkPipelineLayout layout, uint32_t material,
                    bool materialCulling) const;

  // A run of the frame's draw order drawn by one vkCmdDrawIndexed.
  struct DrawRun {
    uint32_t draw;  // index into draws_
    uint32_t firstInstance;
    uint32_t instanceCount;
  };
  std::vector<DrawRun> runs(DrawFilter filter) const;

  Context& context_;
  const Scene& scene_;
  Buffer positions_;
  Buffer vertices_;
  Buffer indices_;
  Buffer materials_;
  Buffer lights_;
  Buffer lightStaging_;  // kept once the lights are uploaded a second time (uploadLights)
  uint32_t lightCount_ = 0;
  uint32_t firstTrailingVpl_ = 0;
  bool vplsTrail_ = true;
  bool shadowedLights_ = false;
  bool secondTexCoords_ = false;
  bool vertexColors_ = false;
  bool textureTransforms_ = false;
  std::vector<Image> textures_;  // scene textures, then neutral white, neutral normal, black
  std::vector<DrawItem> draws_;  // grouped by material
  std::vector<std::vector<uint32_t>> meshInstances_;  // the instances of each mesh
  std::vector<Bounds> instanceBounds_;                // world-space box of each instance, for culling
  std::vector<gpu::MeshInstance> instances_;          // per scene instance
  Buffer frameInstances_;                             // instances in draw order, rewritten by prepareFrame()
  std::vector<uint32_t> meshFirst_;  // this frame: each mesh's visible instances in the order
  std::vector<uint32_t> meshVisible_;
  std::vector<DrawRun> blendRuns_;  // this frame: blended draws, back to front
  uint32_t visibleInstances_ = 0;
  // The distinct samplers of the scene's textures (glTF's samplers), and each texture's.
  std::vector<VkSampler> samplers_;
  std::vector<TextureSampler> samplerKinds_;  // samplers_[i] is samplerKinds_[i]
  std::vector<VkSampler> textureSamplers_;    // per entry of textures_
  VkDescriptorSetLayout materialSetLayout_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> materialSets_;
  VkDescriptorSetLayout textureTableLayout_ = VK_NULL_HANDLE;
  VkDescriptorSet textureTable_ = VK_NULL_HANDLE;
  std::string textureTableProblem_;
};

}  // namespace lll
