#include "shadows/sun_shadows.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <span>

#include "gpu/context.h"
#include "gpu/vk_check.h"
#include "render/frame.h"
#include "render/gpu_scene.h"
#include "render/settings.h"
#include "scene/errors.h"
#include "shadows/shadow_raster.h"

namespace lll {

namespace {

// How far the splits lean from uniform towards logarithmic (the "practical" split scheme), and
// where the logarithmic ones start, as a share of the far plane: from the camera's near plane,
// which reverse depth puts at 1/10,000 of the far one, three of four cascades would cover the
// first few percent of the view.
constexpr float kLogarithmicShare = 0.75f;
constexpr float kLogarithmicStart = 0.01f;
// Lookup biases (SunShadow::bias): the normal offset in texels, the slope bias in texels per unit
// of tan(theta) (2: the PCF taps reach the surface up to 2 texels away, whose depth differs by
// that much), a constant bias in world units per unit of the scene's depth range.
constexpr float kNormalOffsetTexels = 1.0f;
constexpr float kSlopeBiasTexels = 2.0f;
constexpr float kConstantBiasShare = 1e-4f;

constexpr VkShaderStageFlags kCasterStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// The smallest sphere around the slice of a symmetric frustum between view depths d0 and d1, as a
// depth along the view axis and a radius: its corners lie at half-diagonals d * diagonal.
std::pair<float, float> sliceSphere(float d0, float d1, float diagonal) {
  const float a = d0 * diagonal, b = d1 * diagonal;
  float centre = 0.5f * ((b * b - a * a) / (d1 - d0) + d0 + d1);
  centre = std::clamp(centre, d0, d1);
  const float radius = std::max(std::hypot(a, centre - d0), std::hypot(b, d1 - centre));
  return {centre, radius};
}

}  // namespace

SunShadowOptions sunShadowOptions(const RenderSettings& s) {
  SunShadowOptions o;
  if (s.shadows != "sun" && s.shadows != "none")
    throw InputError(fmt::format("--shadows {}: expected sun or none", s.shadows));
  if (s.cascades < 1 || s.cascades > gpu::kMaxCascades)
    throw InputError(fmt::format("--cascades {}: expected 1 to {}", s.cascades, gpu::kMaxCascades));
  if (s.shadowResolution < 16 || s.shadowResolution > 8192)
    throw InputError(fmt::format("--shadow-resolution {}: expected 16 to 8192 texels", s.shadowResolution));
  if (s.shadowFilter != "pcf" && s.shadowFilter != "none")
    throw InputError(fmt::format("--shadow-filter {}: expected pcf or none", s.shadowFilter));
  if (s.shadowRaster != "hardware" && s.shadowRaster != "compute" && s.shadowRaster != "auto")
    throw InputError(fmt::format("--shadow-raster {}: expected hardware, compute or auto", s.shadowRaster));
  o.raster = s.shadowRaster;
  o.cascades = s.shadows == "none" ? 0 : s.cascades;
  o.resolution = s.shadowResolution;
  o.filter = s.shadowFilter == "pcf" ? gpu::kShadowFilterPcf : gpu::kShadowFilterNone;
  return o;
}

int shadowCastingSun(const std::vector<DirectionalLight>& suns) {
  int best = -1;
  float brightest = -1.0f;
  for (size_t i = 0; i < suns.size() && i < gpu::kMaxDirectionalLights; ++i) {
    const float power = suns[i].illuminance * (suns[i].color.r + suns[i].color.g + suns[i].color.b) / 3.0f;
    if (power > brightest) {
      brightest = power;
      best = int(i);
    }
  }
  return best;
}

gpu::SunShadow fitSunCascades(const gpu::FrameUniforms& frame, const glm::vec3& towardSun,
                              const Bounds& scene, const SunShadowOptions& options) {
  gpu::SunShadow out{};
  const uint32_t count = std::clamp(options.cascades, 1u, gpu::kMaxCascades);
  const float near = frame.depthParams.x, far = frame.depthParams.y;
  const float diagonal = std::hypot(frame.depthParams.z, frame.depthParams.w);
  const glm::mat4 cameraToWorld = glm::inverse(frame.view);
  // The sun's frame: a rotation only (its origin the world's), so snapping is in world-fixed texels.
  const glm::vec3 l = glm::normalize(towardSun);
  const glm::vec3 up = std::abs(l.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::mat4 sunView = glm::lookAtRH(glm::vec3(0.0f), -l, up);
  // Depth range: the whole scene along the sun, with a margin so nothing sits on a plane.
  float closest = 1e30f, farthest = -1e30f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner(i & 1 ? scene.max.x : scene.min.x, i & 2 ? scene.max.y : scene.min.y,
                           i & 4 ? scene.max.z : scene.min.z);
    const float depth = -(sunView * glm::vec4(corner, 1.0f)).z;
    closest = std::min(closest, depth);
    farthest = std::max(farthest, depth);
  }
  const float margin = std::max(1e-3f, 0.01f * (farthest - closest));
  closest -= margin;
  farthest += margin;
  const float resolution = float(options.resolution);
  const float logStart = std::max(near, kLogarithmicStart * far);
  float previous = near;
  for (uint32_t c = 0; c < count; ++c) {
    const float t = float(c + 1) / float(count);
    const float split = c + 1 == count ? far
                                       : kLogarithmicShare * logStart * std::pow(far / logStart, t) +
                                             (1.0f - kLogarithmicShare) * (near + (far - near) * t);
    const auto [centreDepth, radius] = sliceSphere(previous, split, diagonal);
    const glm::vec3 centre = glm::vec3(cameraToWorld * glm::vec4(0.0f, 0.0f, -centreDepth, 1.0f));
    const float texel = 2.0f * radius / resolution;
    glm::vec2 middle = glm::vec2(sunView * glm::vec4(centre, 1.0f));
    middle = glm::floor(middle / texel) * texel;
    // Reverse depth, as the camera's: the point nearest the sun at 1, the farthest at 0.
    glm::mat4 projection = glm::orthoRH_ZO(middle.x - radius, middle.x + radius, middle.y - radius,
                                           middle.y + radius, farthest, closest);
    projection[1][1] *= -1.0f;  // y down, as the camera's: front faces keep their winding
    projection[3][1] *= -1.0f;
    out.cascadeViewProj[c] = projection * sunView;
    out.splits[c] = split;
    out.texelWorld[c] = texel;
    previous = split;
  }
  out.bias = glm::vec4(kNormalOffsetTexels, kSlopeBiasTexels, kConstantBiasShare * (farthest - closest),
                       farthest - closest);
  const float columns = float(std::min(count, gpu::kCascadeColumns));
  const float rows = float((count + gpu::kCascadeColumns - 1) / gpu::kCascadeColumns);
  out.atlas = glm::vec4(1.0f / resolution, resolution, 1.0f / columns, 1.0f / rows);
  out.config = glm::uvec4(count, 0u, options.filter, 0u);
  return out;
}

SunShadows::SunShadows(Context& context, const GpuScene& scene, const SunShadowOptions& options)
    : context_(context),
      scene_(scene),
      options_(options),
      sun_(shadowCastingSun(scene.scene().directionalLights)) {
  if (casting()) {
    const uint32_t columns = std::min(options_.cascades, gpu::kCascadeColumns);
    const uint32_t rows = (options_.cascades + gpu::kCascadeColumns - 1) / gpu::kCascadeColumns;
    atlasWidth_ = columns * options_.resolution;
    atlasHeight_ = rows * options_.resolution;
    const uint32_t largest = context.properties().limits.maxImageDimension2D;
    if (atlasWidth_ > largest || atlasHeight_ > largest)
      throw InputError(fmt::format(
          "--shadow-resolution {} with --cascades {}: the shadow atlas would be {}x{} texels; this device's "
          "largest image is {} on a side",
          options_.resolution, options_.cascades, atlasWidth_, atlasHeight_, largest));
  }
  atlas_ = Image(context, atlasWidth_, atlasHeight_, VK_FORMAT_D32_SFLOAT,
                 VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                     VK_IMAGE_USAGE_TRANSFER_DST_BIT,  // the compute rasterizer's copy
                 "sun-shadow-atlas");
  uniforms_ = Buffer(context, sizeof(gpu::SunShadow), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload,
                     "sun-shadow");
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = info.minFilter = VK_FILTER_LINEAR;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.compareEnable = VK_TRUE;
  info.compareOp = VK_COMPARE_OP_GREATER_OR_EQUAL;  // reverse depth: lit where nearer the sun than stored
  VK_CHECK(vkCreateSampler(context.device(), &info, nullptr, &sampler_));
  uniforms_.upload(&data_, sizeof(data_));
  if (!casting()) return;

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
  order_.resize(options_.cascades);
  // auto: compute where it fits, on a GPU (bench/README.md, "The sun's shadow").
  const std::string problem = ShadowRaster::problem(context, atlasWidth_, atlasHeight_);
  if (options_.raster == "compute" && !problem.empty())
    throw InputError(fmt::format("--shadow-raster compute: {}", problem));
  if (options_.raster == "compute" ||
      (options_.raster == "auto" && problem.empty() && !context.isCpuDevice()))
    computeRaster_ = std::make_unique<ShadowRaster>(context, scene, atlasWidth_, atlasHeight_);
  casters_ = Buffer(
      context,
      std::max<size_t>(1, size_t(options_.cascades) * instanceBounds_.size()) * sizeof(gpu::MeshInstance),
      VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUse::Upload, "shadow-casters");
}

SunShadows::~SunShadows() {
  computeRaster_.reset();
  vkDestroySampler(context_.device(), sampler_, nullptr);
}

void SunShadows::orderCasters() {
  const Scene& scene = scene_.scene();
  const uint32_t instances = uint32_t(scene.instances.size());
  std::vector<gpu::MeshInstance> out(size_t(data_.config.x) * instances);
  std::vector<std::pair<float, uint32_t>> byDepth;
  for (uint32_t c = 0; c < data_.config.x; ++c) {
    byDepth.clear();
    for (uint32_t i = 0; i < instances; ++i) {
      const Bounds& b = instanceBounds_[i];
      glm::vec2 lo(1e30f), hi(-1e30f);
      float nearest = -1e30f;
      for (int k = 0; k < 8; ++k) {
        const glm::vec3 corner(k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y,
                               k & 4 ? b.max.z : b.min.z);
        const glm::vec4 clip = data_.cascadeViewProj[c] * glm::vec4(corner, 1.0f);
        lo = glm::min(lo, glm::vec2(clip));
        hi = glm::max(hi, glm::vec2(clip));
        nearest = std::max(nearest, clip.z);  // reverse depth: 1 nearest the sun
      }
      if (hi.x < -1.0f || lo.x > 1.0f || hi.y < -1.0f || lo.y > 1.0f) continue;
      byDepth.push_back({nearest, i});
    }
    std::sort(byDepth.begin(), byDepth.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    order_[c].clear();
    for (const auto& [depth, i] : byDepth) {
      out[size_t(c) * instances + order_[c].size()] = {scene.instances[i].transform, {}};
      order_[c].push_back(i);
    }
  }
  if (!out.empty()) casters_.upload(out.data(), out.size() * sizeof(gpu::MeshInstance));
}

void SunShadows::update(const gpu::FrameUniforms& frame, const Bounds& sceneBounds) {
  if (!casting() || !sceneBounds.valid()) {
    data_ = gpu::SunShadow{};
  } else {
    data_ = fitSunCascades(frame, glm::vec3(frame.sunDirection[0]), sceneBounds, options_);
    // The hardware draws the casters (all of them, or the alpha-masked ones after the compute pass).
    if (!computeRaster_ || hasMasked_) orderCasters();
  }
  uniforms_.upload(&data_, sizeof(data_));
}

void SunShadows::record(FrameContext& frame) {
  constexpr VkPipelineStageFlags2 kReaders = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                                             VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                                             VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  const auto clearOrDraw = [&](VkCommandBuffer cmd) {
    beginRendering(cmd, atlasWidth_, atlasHeight_, {}, atlas_.view(),
                   VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, true);
    if (data_.config.x > 0) {
      drawCasters(frame, cmd, AlphaMode::Opaque);
      drawCasters(frame, cmd, AlphaMode::Mask);
    }
    vkCmdEndRendering(cmd);
  };
  if (data_.config.x == 0) {
    frame.graph.step({uses(atlas_, Use::DepthWrite)}, clearOrDraw);
  } else if (!computeRaster_) {
    frame.graph.pass("shadow-sun", {uses(atlas_, Use::DepthWrite)}, clearOrDraw);
  } else {
    computeRaster_->record(frame, uniforms_, atlas_);
    if (hasMasked_)
      frame.graph.pass("shadow-sun-masked", {uses(atlas_, Use::DepthReadWrite)}, [&](VkCommandBuffer cmd) {
        beginRendering(cmd, atlasWidth_, atlasHeight_, {}, atlas_.view(),
                       VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, false);
        drawCasters(frame, cmd, AlphaMode::Mask);
        vkCmdEndRendering(cmd);
      });
  }
  // Every later pass may read it, in any shader stage: one transition here covers them all.
  frame.graph.step({uses(atlas_, Use::Sampled, kReaders)}, [](VkCommandBuffer) {});
}

void SunShadows::drawCasters(const FrameContext& frame, VkCommandBuffer cmd, AlphaMode mode) const {
  const VkDeviceSize offsets[2] = {0, 0};
  const VkBuffer vertexBuffers[2] = {scene_.vertexBuffer().handle(), casters_.handle()};
  vkCmdBindVertexBuffers(cmd, 0, 2, vertexBuffers, offsets);
  vkCmdBindIndexBuffer(cmd, scene_.indexBuffer().handle(), 0, VK_INDEX_TYPE_UINT32);
  const bool masked = mode == AlphaMode::Mask;
  (masked ? masked_ : opaque_).bind(cmd);
  meshPassDescriptors(frame).push(context_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_);
  const Scene& scene = scene_.scene();
  const uint32_t instances = uint32_t(scene.instances.size());
  const float size = float(options_.resolution);
  for (uint32_t c = 0; c < data_.config.x; ++c) {
    const float x = float(c % gpu::kCascadeColumns) * size, y = float(c / gpu::kCascadeColumns) * size;
    const VkViewport viewport{x, y, size, size, 0.0f, 1.0f};
    const VkRect2D scissor{{int32_t(x), int32_t(y)}, {options_.resolution, options_.resolution}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    const glm::uvec4 cascade(c, 0u, 0u, 0u);
    vkCmdPushConstants(cmd, layout_.handle(), kCasterStages, sizeof(glm::uvec4), sizeof(cascade), &cascade);
    // A single-sided material casts from its front faces only (its back faces do not exist, as
    // glTF culls them when drawing), a double-sided one from both.
    VkCullModeFlags cull = ~0u;
    uint32_t bound = ~0u;
    for (uint32_t slot = 0; slot < order_[c].size(); ++slot)
      for (uint32_t d : (masked ? maskedDraws_ : opaqueDraws_)[scene.instances[order_[c][slot]].mesh]) {
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
        vkCmdDrawIndexed(cmd, item.indexCount, 1, item.firstIndex, int32_t(item.vertexOffset),
                         c * instances + slot);
      }
  }
}

void SunShadows::bind(DescriptorWriter& writer) const {
  writer.storage(26, uniforms_.handle())
      .image(27, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, atlas_.view(),
             VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, sampler_);
}

std::vector<std::pair<std::string, double>> SunShadows::stats() const {
  if (!casting()) return {{"sun-shadow-cascades", 0.0}};
  return {{"sun-shadow-cascades", double(options_.cascades)},
          {"sun-shadow-compute-raster", computeRaster_ ? 1.0 : 0.0},
          {"sun-shadow-resolution", double(options_.resolution)},
          {"sun-shadow_bytes", 4.0 * atlasWidth_ * atlasHeight_}};
}

}  // namespace lll
