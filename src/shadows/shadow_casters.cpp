#include "shadows/shadow_casters.h"

#include <algorithm>

#include "render/frame.h"
#include "render/gpu_scene.h"
#include "shared/shadow_types.h"

namespace lll {

namespace {

constexpr VkShaderStageFlags kCasterStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

glm::vec3 corner(const Bounds& b, int k) {
  return {k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y, k & 4 ? b.max.z : b.min.z};
}

}  // namespace

bool boxMayOverlapView(const glm::mat4& viewProj, const Bounds& box) {
  // Per plane, whether every corner so far lies outside it: x < -w, x > w, y < -w, y > w, z < 0
  // (beyond the far plane) and z > w (nearer than the near plane).
  bool outside[6] = {true, true, true, true, true, true};
  for (int k = 0; k < 8; ++k) {
    const glm::vec4 c = viewProj * glm::vec4(corner(box, k), 1.0f);
    outside[0] = outside[0] && c.x < -c.w;
    outside[1] = outside[1] && c.x > c.w;
    outside[2] = outside[2] && c.y < -c.w;
    outside[3] = outside[3] && c.y > c.w;
    outside[4] = outside[4] && c.z < 0.0f;
    outside[5] = outside[5] && c.z > c.w;
  }
  return std::none_of(std::begin(outside), std::end(outside), [](bool o) { return o; });
}

ShadowCasters::ShadowCasters(Context& context, const GpuScene& scene) : context_(context), scene_(scene) {
  layout_ =
      PipelineLayout(context, {"shadows/caster.vert", "common/depth_mask.frag"}, {scene.materialSetLayout()});
  GraphicsPipelineDesc desc;
  desc.vertexShader = "shadows/caster.vert";
  desc.depthFormat = VK_FORMAT_D32_SFLOAT;
  desc.cullMode = VK_CULL_MODE_NONE;
  desc.depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL;
  opaque_ = Pipeline(context, layout_, desc);
  desc.fragmentShader = "common/depth_mask.frag";
  masked_ = Pipeline(context, layout_, desc);
  instanceBounds_.reserve(scene.scene().instances.size());
  for (const Instance& instance : scene.scene().instances)
    instanceBounds_.push_back(transformBounds(scene.scene().meshBounds(instance.mesh), instance.transform));
  opaqueDraws_.resize(scene.scene().meshes.size());
  maskedDraws_.resize(scene.scene().meshes.size());
  for (uint32_t d = 0; d < scene.draws().size(); ++d) {
    const DrawItem& item = scene.draws()[d];
    const AlphaMode mode = scene.scene().materials[item.material].alphaMode;
    if (mode == AlphaMode::Opaque) opaqueDraws_[item.mesh].push_back(d);
    if (mode == AlphaMode::Mask) maskedDraws_[item.mesh].push_back(d);
  }
  for (const auto& masked : maskedDraws_) hasMasked_ = hasMasked_ || !masked.empty();
}

void ShadowCasters::cull(std::span<const ShadowView> views) {
  const Scene& scene = scene_.scene();
  views_.assign(views.begin(), views.end());
  firstCaster_.clear();
  order_.clear();
  std::vector<std::pair<float, uint32_t>> byDepth;
  for (const ShadowView& view : views) {
    byDepth.clear();
    for (uint32_t i = 0; i < instanceBounds_.size(); ++i) {
      const Bounds& b = instanceBounds_[i];
      if (!boxMayOverlapView(view.viewProj, b)) continue;
      float nearest = 0.0f;  // reverse depth: 1 nearest the light; a corner behind it counts as 1
      for (int k = 0; k < 8; ++k) {
        const glm::vec4 c = view.viewProj * glm::vec4(corner(b, k), 1.0f);
        nearest = std::max(nearest, c.w > 0.0f ? c.z / c.w : 1.0f);
      }
      byDepth.push_back({nearest, i});
    }
    std::sort(byDepth.begin(), byDepth.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    firstCaster_.push_back(uint32_t(order_.size()));
    for (const auto& entry : byDepth) order_.push_back(entry.second);
  }
  firstCaster_.push_back(uint32_t(order_.size()));
  if (order_.empty()) return;
  std::vector<gpu::MeshInstance> transforms(order_.size());
  for (size_t k = 0; k < order_.size(); ++k) transforms[k] = {scene.instances[order_[k]].transform, {}};
  const VkDeviceSize bytes = transforms.size() * sizeof(gpu::MeshInstance);
  // Each frame waits for the last (Renderer::renderFrame), so the buffer may be replaced here.
  if (casters_.size() < bytes)
    casters_ = Buffer(context_, bytes + bytes / 4, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUse::Upload,
                      "shadow-casters");
  casters_.upload(transforms.data(), bytes);
}

void ShadowCasters::draw(const FrameContext& frame, VkCommandBuffer cmd, AlphaMode mode) const {
  if (order_.empty()) return;
  const VkDeviceSize offsets[2] = {0, 0};
  const VkBuffer vertexBuffers[2] = {scene_.vertexBuffer().handle(), casters_.handle()};
  vkCmdBindVertexBuffers(cmd, 0, 2, vertexBuffers, offsets);
  vkCmdBindIndexBuffer(cmd, scene_.indexBuffer().handle(), 0, VK_INDEX_TYPE_UINT32);
  const bool masked = mode == AlphaMode::Mask;
  (masked ? masked_ : opaque_).bind(cmd);
  meshPassDescriptors(frame).push(context_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_);
  const Scene& scene = scene_.scene();
  for (size_t v = 0; v < views_.size(); ++v) {
    const ShadowView& view = views_[v];
    if (firstCaster_[v] == firstCaster_[v + 1]) continue;
    const VkViewport viewport{float(view.x), float(view.y), float(view.size), float(view.size), 0.0f, 1.0f};
    const VkRect2D scissor{{int32_t(view.x), int32_t(view.y)}, {view.size, view.size}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdPushConstants(cmd, layout_.handle(), kCasterStages, sizeof(glm::uvec4), sizeof(glm::mat4),
                       &view.viewProj);
    // A single-sided material casts from its front faces only (its back faces do not exist, as
    // glTF culls them when drawing), a double-sided one from both.
    VkCullModeFlags cull = ~0u;
    uint32_t bound = ~0u;
    for (uint32_t slot = firstCaster_[v]; slot < firstCaster_[v + 1]; ++slot)
      for (uint32_t d : (masked ? maskedDraws_ : opaqueDraws_)[scene.instances[order_[slot]].mesh]) {
        const DrawItem& item = scene_.draws()[d];
        const VkCullModeFlags wanted =
            scene.materials[item.material].doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
        if (wanted != cull) vkCmdSetCullMode(cmd, wanted);
        cull = wanted;
        if (masked && item.material != bound) {
          scene_.bindMaterialSet(cmd, layout_.handle(), item.material);
          const glm::uvec4 ids(item.material, 0u, 0u, 0u);
          vkCmdPushConstants(cmd, layout_.handle(), kCasterStages, 0, sizeof(ids), &ids);
          bound = item.material;
        }
        vkCmdDrawIndexed(cmd, item.indexCount, 1, item.firstIndex, int32_t(item.vertexOffset), slot);
      }
  }
}

}  // namespace lll
