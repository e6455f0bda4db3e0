#include "render/gpu_scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <execution>

#include "core/errors.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"
#include "scene/lights.h"
#include "shared/gpu_types.h"

namespace lll {

namespace {

constexpr uint32_t kTexturesPerMaterial = kTextureSlots;

// The inverse transpose of the model's 3x3, which keeps normals perpendicular under non-uniform
// scales: its cofactor matrix over the determinant. A singular transform (a scale of 0 flattens
// the mesh) has no inverse; its cofactors still give the flattened surface's normal. The first
// column's w is the determinant's sign: -1 where the transform mirrors (the tangent frame turns).
std::array<glm::vec4, 3> normalMatrix(const glm::mat4& model) {
  const glm::dvec3 c0(model[0]), c1(model[1]), c2(model[2]);
  const glm::dmat3 cofactors(glm::cross(c1, c2), glm::cross(c2, c0), glm::cross(c0, c1));
  const double det = glm::dot(c0, glm::cross(c1, c2));
  glm::dmat3 n = cofactors / det;
  for (int i = 0; i < 9; ++i)
    if (!std::isfinite(float(n[i / 3][i % 3]))) n = cofactors;
  return {glm::vec4(glm::vec3(n[0]), det < 0.0 ? -1.0f : 1.0f), glm::vec4(glm::vec3(n[1]), 0.0f),
          glm::vec4(glm::vec3(n[2]), 0.0f)};
}

// The six planes of a Vulkan clip volume (-w <= x, y <= w, 0 <= z <= w) in world space: a point p
// is inside when dot(plane.xyz, p) + plane.w >= 0 for each.
std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProj) {
  const glm::mat4 t = glm::transpose(viewProj);  // rows of viewProj as columns
  return {t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[2], t[3] - t[2]};
}

bool outside(const std::array<glm::vec4, 6>& planes, const Bounds& box) {
  for (const glm::vec4& plane : planes) {
    // The box's corner farthest along the plane's normal: if even it is behind, the box is.
    const glm::vec3 far(plane.x >= 0.0f ? box.max.x : box.min.x, plane.y >= 0.0f ? box.max.y : box.min.y,
                        plane.z >= 0.0f ? box.max.z : box.min.z);
    if (glm::dot(glm::vec3(plane), far) + plane.w < 0.0f) return true;
  }
  return false;
}

uint32_t mipLevelsFor(uint32_t width, uint32_t height) {
  return uint32_t(std::floor(std::log2(double(std::max(width, height))))) + 1;
}

// Uploads RGBA8 pixels and fills the mip chain by successive linear blits.
VkSamplerAddressMode addressMode(TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::ClampToEdge:
      return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case TextureWrap::MirroredRepeat:
      return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case TextureWrap::Repeat:
      break;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

VkSampler createSampler(Context& context, const TextureSampler& sampler) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = sampler.magnify == TextureFilter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
  info.minFilter = sampler.minify == TextureFilter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
  info.mipmapMode =
      sampler.mip == MipFilter::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = addressMode(sampler.wrapU);
  info.addressModeV = addressMode(sampler.wrapV);
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  // Without mip levels: the base level only, still choosing the minification filter where the
  // texture shrinks (Vulkan's equivalent of OpenGL's non-mipmapped filters: maxLod 0.25 with
  // nearest mip selection).
  info.maxLod = sampler.mip == MipFilter::None ? 0.25f : VK_LOD_CLAMP_NONE;
  VkSampler out = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSampler(context.device(), &info, nullptr, &out));
  return out;
}

Image makeTexture(Context& context, const Texture& texture) {
  // lavapipe (Mesa 22.3) crashes in LLVM compiling textureLod of an 8-bit UNORM texture through a
  // sampler array indexed at run time (the visibility path's table, common/visibility_surface.glsl;
  // any glTF with a normal or metallic-roughness map): on a CPU device those textures are 16-bit
  // UNORM, each 8-bit value v stored as 257 v, the same number.
  const bool wide = !texture.srgb && context.isCpuDevice();
  const VkFormat format = texture.srgb ? VK_FORMAT_R8G8B8A8_SRGB
                          : wide       ? VK_FORMAT_R16G16B16A16_UNORM
                                       : VK_FORMAT_R8G8B8A8_UNORM;
  std::vector<uint16_t> widened;
  if (wide) {
    widened.reserve(texture.rgba.size());
    for (uint8_t v : texture.rgba) widened.push_back(uint16_t(v * 257u));
  }
  const void* texels = wide ? static_cast<const void*>(widened.data()) : texture.rgba.data();
  const size_t bytes = wide ? widened.size() * sizeof(uint16_t) : texture.rgba.size();
  const uint32_t levels = mipLevelsFor(texture.width, texture.height);
  Image image(context, texture.width, texture.height, format,
              VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
              texture.name, levels);
  uploadImage(context, image, texels, bytes, [&](VkCommandBuffer cmd) {
    int32_t w = int32_t(texture.width), h = int32_t(texture.height);
    for (uint32_t level = 1; level < levels; ++level) {
      VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
      barrier.srcStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
      barrier.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
      barrier.dstStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
      barrier.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
      barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
      barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      barrier.image = image.handle();
      barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 1, 0, 1};
      VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
      dependency.imageMemoryBarrierCount = 1;
      dependency.pImageMemoryBarriers = &barrier;
      vkCmdPipelineBarrier2(cmd, &dependency);
      VkImageBlit blit{};
      blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1};
      blit.srcOffsets[1] = {w, h, 1};
      w = std::max(1, w / 2);
      h = std::max(1, h / 2);
      blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
      blit.dstOffsets[1] = {w, h, 1};
      vkCmdBlitImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.handle(),
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
    }
    // Levels below the last are in TRANSFER_SRC, the last in TRANSFER_DST: move each to shader reads.
    for (uint32_t level = 0; level < levels; ++level) {
      VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
      barrier.srcStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
      barrier.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_TRANSFER_READ_BIT;
      barrier.dstStageMask = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
      barrier.dstAccessMask = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
      barrier.oldLayout =
          level + 1 < levels ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
      barrier.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
      barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      barrier.image = image.handle();
      barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, 1};
      VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
      dependency.imageMemoryBarrierCount = 1;
      dependency.pImageMemoryBarriers = &barrier;
      vkCmdPipelineBarrier2(cmd, &dependency);
    }
  });
  return image;
}

Texture solidTexture(const char* name, uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
  Texture t;
  t.name = name;
  t.width = t.height = 1;
  t.rgba = {r, g, b, a};
  return t;
}

}  // namespace

GpuScene::GpuScene(Context& context, const Scene& scene) : context_(context), scene_(scene) {
  uploadGeometry();
  uploadInstances();
  uploadMaterials();
  uploadLights(scene.lights);
  uploadTextures();
  createMaterialSets();
  createTextureTable();
}

GpuScene::~GpuScene() {
  VkDevice device = context_.device();
  vkDestroyDescriptorPool(device, descriptorPool_, nullptr);
  vkDestroyDescriptorSetLayout(device, materialSetLayout_, nullptr);
  vkDestroyDescriptorSetLayout(device, textureTableLayout_, nullptr);
  for (VkSampler sampler : samplers_) vkDestroySampler(device, sampler, nullptr);
}

void GpuScene::uploadGeometry() {
  const VkBufferUsageFlags geometry = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  vertices_ = Buffer(context_, scene_.vertices.size() * sizeof(Vertex),
                     geometry | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUse::Device, "vertices");
  vertices_.upload(std::span<const Vertex>(scene_.vertices));
  indices_ = Buffer(context_, scene_.indices.size() * sizeof(uint32_t),
                    geometry | VK_BUFFER_USAGE_INDEX_BUFFER_BIT, MemoryUse::Device, "indices");
  indices_.upload(std::span<const uint32_t>(scene_.indices));
  std::vector<glm::vec3> positions;
  positions.reserve(scene_.vertices.size());
  const glm::uvec2 white(Vertex::kWhiteHalf2);
  for (const Vertex& v : scene_.vertices) {
    positions.push_back(v.position);
    vertexColors_ |= v.color != white;
  }
  for (const Material& m : scene_.materials)
    for (uint32_t slot = 0; slot < kTextureSlots; ++slot)
      if (m.texture(TextureSlot(slot)) >= 0) {
        secondTexCoords_ |= m.texCoords[slot] == 1;
        textureTransforms_ |= !m.transforms[slot].identity();
      }
  positions_ = Buffer(context_, positions.size() * sizeof(glm::vec3),
                      VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                      MemoryUse::Device, "positions");
  positions_.upload(std::span<const glm::vec3>(positions));
  meshInstances_.resize(scene_.meshes.size());
  for (uint32_t i = 0; i < scene_.instances.size(); ++i)
    meshInstances_[scene_.instances[i].mesh].push_back(i);
  for (uint32_t mesh = 0; mesh < scene_.meshes.size(); ++mesh) {
    if (meshInstances_[mesh].empty()) continue;
    for (const Primitive& p : scene_.meshes[mesh].primitives) {
      if (p.indexCount == 0) continue;
      Bounds local;
      for (uint32_t k = 0; k < p.indexCount; ++k)
        local.expand(scene_.vertices[p.vertexOffset + scene_.indices[p.firstIndex + k]].position);
      draws_.push_back({mesh, p.firstIndex, p.indexCount, p.vertexOffset, p.material, local.center()});
    }
  }
  // One material bind per material and pass.
  std::stable_sort(draws_.begin(), draws_.end(),
                   [](const DrawItem& a, const DrawItem& b) { return a.material < b.material; });
}

// Each instance's transform and normal matrix once, on the CPU. The frame's instance buffer has
// room for every instance once (opaque draws) plus once per blended primitive of its mesh (blended
// draws); a device that cannot hold it is refused with the numbers, rather than drawing only some.
void GpuScene::uploadInstances() {
  instances_.reserve(scene_.instances.size());
  std::vector<Bounds> local(scene_.meshes.size());
  for (uint32_t mesh = 0; mesh < scene_.meshes.size(); ++mesh)
    if (!meshInstances_[mesh].empty()) local[mesh] = scene_.meshBounds(mesh);
  for (const Instance& instance : scene_.instances) {
    const auto n = normalMatrix(instance.transform);
    instances_.push_back({instance.transform, {n[0], n[1], n[2]}});
    instanceBounds_.push_back(transformBounds(local[instance.mesh], instance.transform));
  }
  uint64_t entries = scene_.instances.size();
  for (const DrawItem& d : draws_)
    if (scene_.materials[d.material].alphaMode == AlphaMode::Blend) entries += meshInstances_[d.mesh].size();
  const uint64_t bytes = std::max<uint64_t>(1, entries) * sizeof(gpu::MeshInstance);
  try {
    frameInstances_ =
        Buffer(context_, bytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
               MemoryUse::Upload, "instances");
  } catch (const VulkanError& e) {
    throw InputError(
        fmt::format("{} instances ({} per frame with the blended draws) need {:.1f} MiB of "
                    "instance data, which this device cannot allocate ({})",
                    scene_.instances.size(), entries, double(bytes) / 1048576.0, e.what()));
  }
  meshFirst_.assign(scene_.meshes.size(), 0);
  meshVisible_.assign(scene_.meshes.size(), 0);
}

void GpuScene::uploadMaterials() {
  std::vector<gpu::GpuMaterial> materials;
  for (const Material& m : scene_.materials) {
    gpu::GpuMaterial g{};
    g.baseColorFactor = m.baseColorFactor;
    g.emissive = glm::vec4(m.emissiveFactor * m.emissiveStrength, 0.0f);
    g.params = glm::vec4(m.metallic, m.roughness, m.normalScale, m.occlusionStrength);
    const TextureSlots slots = textureSlots(m);
    // Which textures the material has (the rest are the stand-ins after the scene's own): the
    // surface rebuild samples only those.
    constexpr uint32_t kBits[kTexturesPerMaterial] = {
        gpu::kMaterialBaseColorTexture, gpu::kMaterialMetallicRoughnessTexture, gpu::kMaterialNormalTexture,
        gpu::kMaterialEmissiveTexture, gpu::kMaterialOcclusionTexture};
    uint32_t textures = 0;
    for (uint32_t i = 0; i < kTexturesPerMaterial; ++i)
      if (slots[i] < scene_.textures.size()) textures |= kBits[i];
    for (uint32_t slot = 0; slot < kTextureSlots; ++slot) {
      const TextureTransform& t = m.transforms[slot];
      if (!t.identity()) textures |= gpu::kMaterialTextureTransform;
      if (m.texCoords[slot] == 1) textures |= gpu::kMaterialSecondTexCoord << slot;
      const glm::mat2 linear = t.linear();
      g.uvMatrix[slot] = glm::vec4(linear[0], linear[1]);
      g.uvOffset[slot / 2][2 * (slot % 2)] = t.offset.x;
      g.uvOffset[slot / 2][2 * (slot % 2) + 1] = t.offset.y;
    }
    g.flags = glm::uvec4(uint32_t(m.alphaMode), m.doubleSided ? 1u : 0u, textures, slots[4]);
    g.alpha = glm::vec4(m.alphaCutoff, 0.0f, 0.0f, 0.0f);
    g.textures = glm::uvec4(slots[0], slots[1], slots[2], slots[3]);
    materials.push_back(g);
  }
  materials_ = Buffer(context_, materials.size() * sizeof(gpu::GpuMaterial),
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Device, "materials");
  materials_.upload(std::span<const gpu::GpuMaterial>(materials));
}

void GpuScene::uploadLights(const std::vector<Light>& lights) {
  const VkDeviceSize bytes = lights.size() * sizeof(gpu::GpuLight);
  const bool uploadedBefore = bool(lights_);  // made here only
  // Also a uniform buffer of its first kUniformLightRecordBytes (common/frame.glsl's binding 51),
  // which it therefore always spans.
  if (!lights_ || lights_.size() < bytes)
    lights_ = Buffer(context_, std::max(bytes, kUniformLightRecordBytes),
                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                     MemoryUse::Device, "lights");
  // The records are converted on every core straight into the staging buffer. The first upload's
  // staging is freed with it; from the second on (lights placed on the CPU every frame) it is kept
  // for the next frame: a million lights' 64 MB were 90 ms a frame on a 2-core machine when each
  // frame converted into a vector, allocated a new staging buffer and copied it there
  // (bench/README.md, "CPU only, 2026-12-05 (third)").
  Buffer temporary;
  Buffer& staging = uploadedBefore ? lightStaging_ : temporary;
  if (!staging || staging.size() < bytes)
    staging = Buffer(context_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload, "light staging");
  std::transform(std::execution::par, lights.begin(), lights.end(),
                 static_cast<gpu::GpuLight*>(staging.mapped()), toGpuLight);
  lights_.copyFrom(staging, bytes);
  lightCount_ = uint32_t(lights.size());
  firstTrailingVpl_ = lightCount_;
  while (firstTrailingVpl_ > 0 && lights[firstTrailingVpl_ - 1].type == LightType::Vpl) --firstTrailingVpl_;
  vplsTrail_ = std::none_of(lights.begin(), lights.begin() + firstTrailingVpl_,
                            [](const Light& l) { return l.type == LightType::Vpl; });
}

void GpuScene::uploadTextures() {
  for (const Texture& texture : scene_.textures) textures_.push_back(makeTexture(context_, texture));
  textures_.push_back(makeTexture(context_, solidTexture("white", 255, 255, 255, 255)));
  textures_.push_back(makeTexture(context_, solidTexture("flat-normal", 128, 128, 255, 255)));
  // One Vulkan sampler for each distinct glTF sampler; the stand-ins take the default.
  for (size_t i = 0; i < textures_.size(); ++i) {
    const TextureSampler wanted = i < scene_.textures.size() ? scene_.textures[i].sampler : TextureSampler{};
    auto known = std::find(samplerKinds_.begin(), samplerKinds_.end(), wanted);
    if (known == samplerKinds_.end()) {
      samplers_.push_back(createSampler(context_, wanted));
      samplerKinds_.push_back(wanted);
      known = samplerKinds_.end() - 1;
    }
    textureSamplers_.push_back(samplers_[size_t(known - samplerKinds_.begin())]);
  }
}

void GpuScene::createMaterialSets() {
  VkDescriptorSetLayoutBinding bindings[kTexturesPerMaterial];
  for (uint32_t i = 0; i < kTexturesPerMaterial; ++i)
    bindings[i] = {i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  layoutInfo.bindingCount = kTexturesPerMaterial;
  layoutInfo.pBindings = bindings;
  VK_CHECK(vkCreateDescriptorSetLayout(context_.device(), &layoutInfo, nullptr, &materialSetLayout_));

  // The material sets, and the texture table (createTextureTable).
  const uint32_t setCount = std::max<uint32_t>(1, uint32_t(scene_.materials.size()));
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                            setCount * kTexturesPerMaterial + textureCount()};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = setCount + 1;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &size;
  VK_CHECK(vkCreateDescriptorPool(context_.device(), &poolInfo, nullptr, &descriptorPool_));

  std::vector<VkDescriptorSetLayout> layouts(scene_.materials.size(), materialSetLayout_);
  materialSets_.resize(scene_.materials.size());
  if (materialSets_.empty()) return;
  VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocInfo.descriptorPool = descriptorPool_;
  allocInfo.descriptorSetCount = uint32_t(layouts.size());
  allocInfo.pSetLayouts = layouts.data();
  VK_CHECK(vkAllocateDescriptorSets(context_.device(), &allocInfo, materialSets_.data()));
  for (size_t m = 0; m < scene_.materials.size(); ++m) {
    const TextureSlots slots = textureSlots(scene_.materials[m]);
    VkDescriptorImageInfo images[kTexturesPerMaterial];
    VkWriteDescriptorSet writes[kTexturesPerMaterial];
    for (uint32_t i = 0; i < kTexturesPerMaterial; ++i) {
      images[i] = {textureSamplers_[slots[i]], textures_[slots[i]].view(),
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
      writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      writes[i].dstSet = materialSets_[m];
      writes[i].dstBinding = i;
      writes[i].descriptorCount = 1;
      writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      writes[i].pImageInfo = &images[i];
    }
    vkUpdateDescriptorSets(context_.device(), kTexturesPerMaterial, writes, 0, nullptr);
  }
}

GpuScene::TextureSlots GpuScene::textureSlots(const Material& material) const {
  const uint32_t white = uint32_t(scene_.textures.size());
  const uint32_t flatNormal = white + 1;
  TextureSlots slots{};
  for (uint32_t i = 0; i < kTexturesPerMaterial; ++i) {
    const int given = material.texture(TextureSlot(i));
    const bool valid = given >= 0 && size_t(given) < scene_.textures.size();
    slots[i] = valid ? uint32_t(given) : (i == kNormalSlot ? flatNormal : white);
  }
  return slots;
}

// One array of every texture for compute passes that shade any material: lavapipe has no
// descriptor indexing and binds at most 128 sampled images a stage, so the array is exactly as
// long as the scene needs and is indexed only with workgroup-uniform indices
// (common/visibility_surface.glsl).
void GpuScene::createTextureTable() {
  const uint32_t count = textureCount();
  const uint32_t limit = context_.properties().limits.maxPerStageDescriptorSampledImages;
  if (count > limit) {
    textureTableProblem_ =
        fmt::format("the scene has {} textures and {} binds at most {} in one shader stage", count,
                    context_.info().name, limit);
    return;
  }
  const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, count,
                                             VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  layoutInfo.bindingCount = 1;
  layoutInfo.pBindings = &binding;
  VK_CHECK(vkCreateDescriptorSetLayout(context_.device(), &layoutInfo, nullptr, &textureTableLayout_));
  VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocInfo.descriptorPool = descriptorPool_;
  allocInfo.descriptorSetCount = 1;
  allocInfo.pSetLayouts = &textureTableLayout_;
  VK_CHECK(vkAllocateDescriptorSets(context_.device(), &allocInfo, &textureTable_));
  std::vector<VkDescriptorImageInfo> images;
  for (size_t i = 0; i < textures_.size(); ++i)
    images.push_back({textureSamplers_[i], textures_[i].view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = textureTable_;
  write.dstBinding = 0;
  write.descriptorCount = count;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = images.data();
  vkUpdateDescriptorSets(context_.device(), 1, &write, 0, nullptr);
}

bool GpuScene::matches(const DrawItem& item, DrawFilter filter) const {
  const AlphaMode mode = scene_.materials[item.material].alphaMode;
  switch (filter) {
    case DrawFilter::OpaqueOnly:
      return mode == AlphaMode::Opaque;
    case DrawFilter::MaskOnly:
      return mode == AlphaMode::Mask;
    case DrawFilter::Opaque:
      return mode != AlphaMode::Blend;
    case DrawFilter::Blend:
      return mode == AlphaMode::Blend;
    case DrawFilter::All:
      return true;
  }
  return false;
}

bool GpuScene::hasBlendDraws() const {
  return std::any_of(draws_.begin(), draws_.end(),
                     [&](const DrawItem& d) { return matches(d, DrawFilter::Blend); });
}

void GpuScene::prepareFrame(const glm::mat4& viewProj, const glm::vec3& eye) {
  const auto planes = frustumPlanes(viewProj);
  auto* order = static_cast<gpu::MeshInstance*>(frameInstances_.mapped());
  uint32_t written = 0;
  visibleInstances_ = 0;
  std::vector<bool> visible(scene_.instances.size());
  for (uint32_t mesh = 0; mesh < meshInstances_.size(); ++mesh) {
    meshFirst_[mesh] = written;
    for (uint32_t instance : meshInstances_[mesh]) {
      visible[instance] = !outside(planes, instanceBounds_[instance]);
      if (visible[instance]) order[written++] = instances_[instance];
    }
    meshVisible_[mesh] = written - meshFirst_[mesh];
    visibleInstances_ += meshVisible_[mesh];
  }
  // Blended draws: every visible (primitive, instance) pair, farthest first, then runs of one
  // primitive drawn together.
  struct Blended {
    float distance2;
    uint32_t draw;
    uint32_t instance;
  };
  std::vector<Blended> blended;
  for (uint32_t d = 0; d < draws_.size(); ++d) {
    if (!matches(draws_[d], DrawFilter::Blend)) continue;
    for (uint32_t instance : meshInstances_[draws_[d].mesh]) {
      if (!visible[instance]) continue;
      const glm::vec3 center(scene_.instances[instance].transform * glm::vec4(draws_[d].center, 1.0f));
      blended.push_back({glm::dot(center - eye, center - eye), d, instance});
    }
  }
  std::stable_sort(blended.begin(), blended.end(),
                   [](const Blended& a, const Blended& b) { return a.distance2 > b.distance2; });
  blendRuns_.clear();
  for (const Blended& b : blended) {
    if (blendRuns_.empty() || blendRuns_.back().draw != b.draw) blendRuns_.push_back({b.draw, written, 0});
    order[written++] = instances_[b.instance];
    ++blendRuns_.back().instanceCount;
  }
}

void GpuScene::bindMaterialSet(VkCommandBuffer cmd, VkPipelineLayout layout, uint32_t material) const {
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 1, 1, &materialSets_[material], 0,
                          nullptr);
}

void GpuScene::bindMaterial(VkCommandBuffer cmd, VkPipelineLayout layout, uint32_t material,
                            bool materialCulling) const {
  bindMaterialSet(cmd, layout, material);
  if (materialCulling)
    vkCmdSetCullMode(cmd, scene_.materials[material].doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
  const gpu::DrawPush push{glm::uvec4(material, 0, 0, 0)};
  vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push),
                     &push);
}

std::vector<GpuScene::DrawRun> GpuScene::runs(DrawFilter filter) const {
  if (filter == DrawFilter::Blend) return blendRuns_;
  std::vector<DrawRun> runs;
  for (uint32_t d = 0; d < draws_.size(); ++d) {
    const uint32_t mesh = draws_[d].mesh;
    if (matches(draws_[d], filter) && meshVisible_[mesh] > 0)
      runs.push_back({d, meshFirst_[mesh], meshVisible_[mesh]});
  }
  return runs;
}

void GpuScene::draw(VkCommandBuffer cmd, VkPipelineLayout layout, DrawFilter filter,
                    bool materialCulling) const {
  const std::vector<DrawRun> runs = this->runs(filter);
  if (runs.empty()) return;
  const VkDeviceSize offsets[2] = {0, 0};
  const VkBuffer vertexBuffers[2] = {vertices_.handle(), frameInstances_.handle()};
  vkCmdBindVertexBuffers(cmd, 0, 2, vertexBuffers, offsets);
  vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
  uint32_t boundMaterial = ~0u;
  for (const DrawRun& run : runs) {
    const DrawItem& d = draws_[run.draw];
    if (d.material != boundMaterial) bindMaterial(cmd, layout, d.material, materialCulling);
    boundMaterial = d.material;
    vkCmdDrawIndexed(cmd, d.indexCount, run.instanceCount, d.firstIndex, int32_t(d.vertexOffset),
                     run.firstInstance);
  }
}

}  // namespace lll
