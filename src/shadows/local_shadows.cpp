#include "shadows/local_shadows.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "gpu/context.h"
#include "render/frame.h"
#include "render/gpu_scene.h"
#include "render/settings.h"

namespace lll {

namespace {

// Texels of margin on each side of a view, so the filter's taps near its edge read real depths.
constexpr float kMarginTexels = 2.0f;
// The near plane, as a share of the light's range (at least kNearest metres).
constexpr float kNearShare = 0.005f;
constexpr float kNearest = 1e-3f;
// The largest atlas (bytes of 32-bit depth) the lights may take.
constexpr double kMostAtlasBytes = 2.0 * 1024 * 1024 * 1024;

// Reverse depth (1 at `near`, 0 at `far`), y down as the camera's: a square view of half-angle
// tangent `tanHalf`.
glm::mat4 projection(float tanHalf, float near, float far) {
  glm::mat4 p = glm::perspectiveRH_ZO(2.0f * std::atan(tanHalf), 1.0f, far, near);
  p[1][1] *= -1.0f;
  return p;
}

glm::vec3 anyPerpendicular(const glm::vec3& d) {
  return std::abs(d.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
}

float tanHalfWithMargin(float tanHalf, uint32_t resolution) {
  return tanHalf * (1.0f + 2.0f * kMarginTexels / float(resolution));
}

}  // namespace

LocalShadowOptions localShadowOptions(const RenderSettings& s) {
  LocalShadowOptions o;
  if (s.shadowLights > gpu::kMaxShadowLights)
    throw InputError(
        fmt::format("--shadow-lights {}: expected 0 to {}", s.shadowLights, gpu::kMaxShadowLights));
  if (s.shadowLightResolution < 16 || s.shadowLightResolution > 4096)
    throw InputError(
        fmt::format("--shadow-light-resolution {}: expected 16 to 4096 texels", s.shadowLightResolution));
  o.lights = s.shadows == ShadowMode::All ? s.shadowLights : 0;
  o.resolution = s.shadowLightResolution;
  o.filter = s.shadowFilter == ShadowFilter::None ? gpu::kShadowFilterNone : gpu::kShadowFilterPcf;
  o.raster = s.shadowRaster;
  return o;
}

bool castsThroughCube(const Light& light) {
  return light.type == LightType::Point ||
         (light.type == LightType::Spot && light.outerConeAngle > kWidestShadowCone);
}

float shadowImportance(const Light& light, const gpu::FrameUniforms& frame) {
  if (light.type != LightType::Point && light.type != LightType::Spot) return 0.0f;
  const float power = light.intensity * (light.color.r + light.color.g + light.color.b) / 3.0f;
  // A reach beyond kFarthestShadow has no finite view (its near plane times its far one overflows).
  if (!(power > 0.0f) || !(light.range > 0.0f) || !(light.range <= kFarthestShadow)) return 0.0f;
  if (!std::isfinite(light.position.x + light.position.y + light.position.z)) return 0.0f;
  const glm::vec3 c = glm::vec3(frame.view * glm::vec4(light.position, 1.0f));
  const float r = light.range, depth = -c.z;
  const float tanX = frame.depthParams.z, tanY = frame.depthParams.w;
  // Outside the frustum: beyond a side plane (normals (1, 0, tanX) / |..| etc., through the eye)
  // or behind the near plane / beyond the far one.
  if (depth + r < frame.depthParams.x || depth - r > frame.depthParams.y) return 0.0f;
  if (std::abs(c.x) - depth * tanX > r * std::sqrt(1.0f + tanX * tanX)) return 0.0f;
  if (std::abs(c.y) - depth * tanY > r * std::sqrt(1.0f + tanY * tanY)) return 0.0f;
  const float d2 = glm::dot(c, c);
  if (d2 <= r * r) return power;  // the camera is inside its reach: all of the screen
  // The sphere's angular radius, as a share of the view's area (its disc over the view's rectangle).
  const float tanAngle2 = r * r / (d2 - r * r);
  const float coverage = std::min(1.0f, 0.25f * 3.14159265f * tanAngle2 / (tanX * tanY));
  return coverage * power;
}

std::vector<uint32_t> selectShadowLights(const std::vector<Light>& lights, const gpu::FrameUniforms& frame,
                                         uint32_t count, std::span<const uint32_t> previous) {
  std::vector<float> score(lights.size());
  for (size_t i = 0; i < lights.size(); ++i) score[i] = shadowImportance(lights[i], frame);
  for (uint32_t i : previous)
    if (i < score.size()) score[i] *= kKeepShadow;
  std::vector<uint32_t> candidates;
  for (uint32_t i = 0; i < score.size(); ++i)
    if (score[i] > 0.0f) candidates.push_back(i);
  const auto better = [&](uint32_t a, uint32_t b) {
    return score[a] != score[b] ? score[a] > score[b] : a < b;
  };
  const size_t kept = std::min<size_t>(count, candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + kept, candidates.end(), better);
  candidates.resize(kept);
  return candidates;
}

std::vector<LightView> shadowViews(const Light& light, uint32_t resolution) {
  const float far = light.range, near = std::max(kNearest, kNearShare * light.range);
  std::vector<LightView> out;
  if (!castsThroughCube(light)) {
    const glm::vec3 d = glm::normalize(light.direction);
    const glm::mat4 view = glm::lookAtRH(light.position, light.position + d, anyPerpendicular(d));
    const float tanHalf = tanHalfWithMargin(std::tan(light.outerConeAngle), resolution);
    out.push_back({projection(tanHalf, near, far) * view, tanHalf});
    return out;
  }
  const float tanHalf = tanHalfWithMargin(1.0f, resolution);
  const glm::mat4 p = projection(tanHalf, near, far);
  const glm::vec3 faces[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::vec3& d : faces)
    out.push_back({p * glm::lookAtRH(light.position, light.position + d, anyPerpendicular(d)), tanHalf});
  return out;
}

LocalShadows::LocalShadows(Context& context, const GpuScene& scene, const LocalShadowOptions& options)
    : context_(context), scene_(scene), options_(options) {
  uint32_t singles = 0, cubes = 0;
  for (const Light& light : scene.scene().lights) {
    if (light.type != LightType::Point && light.type != LightType::Spot) continue;
    (castsThroughCube(light) ? cubes : singles) += 1;
  }
  // Any K of the lights fit: each pool holds as many as could be chosen from it.
  spotSlots_ = std::min(options_.lights, singles);
  cubeSlots_ = std::min(options_.lights, cubes);
  const uint32_t views = spotSlots_ + 6 * cubeSlots_;
  ShadowAtlasDesc atlas;
  atlas.image = "light-shadow-atlas";
  atlas.pass = "shadow-lights";
  atlas.raster = options_.raster;
  atlas.request = "--shadow-raster compute with --shadows all";
  if (casting()) {
    const uint32_t size = options_.resolution;
    const uint32_t largest = context.properties().limits.maxImageDimension2D;
    columns_ = std::max(1u, std::min(views, largest / size));
    atlas.width = columns_ * size;
    atlas.height = (views + columns_ - 1) / columns_ * size;
    atlas.maxViews = views;
    const double bytes = 4.0 * atlas.width * atlas.height;
    if (atlas.height > largest || bytes > kMostAtlasBytes) {
      // The most lights that fit, if every one chosen were of the larger kind the scene has.
      const double fitViews =
          std::min(double(largest / size) * double(largest / size), kMostAtlasBytes / (4.0 * size * size));
      const uint32_t perLight = cubes > 0 ? 6 : 1;
      throw InputError(fmt::format(
          "--shadow-lights {} at --shadow-light-resolution {}: {} shadow views need a {}x{} depth atlas "
          "({:.0f} MiB); this device's largest image is {} on a side and the atlas may take at most {:.0f} "
          "MiB: at most {} lights fit at this resolution",
          options_.lights, size, views, atlas.width, atlas.height, bytes / 1048576.0, largest,
          kMostAtlasBytes / 1048576.0, uint32_t(fitViews) / perLight));
    }
  }
  atlas_ = ShadowAtlas(context, scene, atlas);
  views_.assign(std::max(1u, views), gpu::LocalShadowView{});
  viewBuffer_ = Buffer(context, views_.size() * sizeof(gpu::LocalShadowView),
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload, "light-shadow-views");
  viewBuffer_.upload(views_.data(), views_.size() * sizeof(gpu::LocalShadowView));
}

void LocalShadows::update(const gpu::FrameUniforms& frame) {
  if (!casting()) return;
  const std::vector<Light>& lights = scene_.scene().lights;
  std::vector<uint32_t> previous;
  for (const auto& entry : slots_) previous.push_back(entry.first);
  const std::vector<uint32_t> chosen = selectShadowLights(lights, frame, options_.lights, previous);
  // Those that stay keep their slots; the others' slots are freed for the newcomers.
  std::unordered_map<uint32_t, Slot> kept;
  for (uint32_t i : chosen)
    if (auto it = slots_.find(i); it != slots_.end()) kept.insert(*it);
  std::vector<bool> usedSpot(spotSlots_), usedCube(cubeSlots_);
  for (const auto& [light, slot] : kept) (slot.cube ? usedCube : usedSpot)[slot.index] = true;
  uint32_t nextSpot = 0, nextCube = 0;
  for (uint32_t i : chosen) {
    if (kept.count(i)) continue;
    Slot slot;
    slot.cube = castsThroughCube(lights[i]);
    uint32_t& next = slot.cube ? nextCube : nextSpot;
    std::vector<bool>& used = slot.cube ? usedCube : usedSpot;
    while (used[next]) ++next;  // a pool holds min(K, its lights): a free slot remains
    used[next] = true;
    slot.index = next;
    kept[i] = slot;
  }
  // The light records to rewrite: those whose views changed, and those that stopped casting.
  for (const auto& [light, slot] : slots_)
    if (!kept.count(light)) changes_.push_back({light, 0.0f});
  for (const auto& [light, slot] : kept)
    if (auto it = slots_.find(light); it == slots_.end() || recordValue(it->second) != recordValue(slot))
      changes_.push_back({light, recordValue(slot)});
  slots_ = std::move(kept);
  // Each casting light's views, in its cells.
  std::fill(views_.begin(), views_.end(), gpu::LocalShadowView{});
  std::vector<ShadowView> drawn;
  const uint32_t size = options_.resolution;
  for (const auto& [light, slot] : slots_) {
    const std::vector<LightView> lightViews = shadowViews(lights[light], size);
    for (uint32_t f = 0; f < lightViews.size(); ++f) {
      const uint32_t v = firstView(slot) + f;
      const uint32_t x = v % columns_ * size, y = v / columns_ * size;
      gpu::LocalShadowView& out = views_[v];
      out.viewProj = lightViews[f].viewProj;
      const glm::vec2 atlasSize(atlas_.width(), atlas_.height());
      out.cell = glm::vec4(glm::vec2(x, y) / atlasSize, glm::vec2(size) / atlasSize);
      // A texel's world size per unit of distance along the view: its width at distance 1 over its texels.
      out.params = glm::vec4(2.0f * lightViews[f].tanHalf / float(size), gpu::kShadowNormalOffsetTexels,
                             gpu::kShadowSlopeBiasTexels, 1.0f / float(size));
      out.config = glm::uvec4(options_.filter, 0u, 0u, 0u);
      drawn.push_back(
          {lightViews[f].viewProj, x, y, size, glm::vec4(lights[light].position, lights[light].range)});
    }
  }
  viewBuffer_.upload(views_.data(), views_.size() * sizeof(gpu::LocalShadowView));
  viewsDrawn_ = uint32_t(drawn.size());
  atlas_.setViews(drawn);
}

void LocalShadows::record(FrameContext& frame) {
  if (!changes_.empty()) {
    // The light array is otherwise written once, at load: every pass reads it without declaring
    // it, so the barriers around the rewrite are explicit. Before: the last frame's reads.
    frame.graph.step({}, [&](VkCommandBuffer cmd) {
      memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT,
                    VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
      const VkBuffer lights = frame.scene.lightBuffer().handle();
      for (const auto& [light, value] : changes_)
        vkCmdUpdateBuffer(cmd, lights,
                          VkDeviceSize(light) * sizeof(gpu::GpuLight) + offsetof(gpu::GpuLight, spotParams) +
                              3 * sizeof(float),
                          sizeof(float), &value);
      // After: every reader of the frame.
      memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
    });
    changes_.clear();  // written: a frame recorded again has nothing to rewrite
  }
  atlas_.record(frame);
}

void LocalShadows::lightsRewritten() {
  for (const auto& [light, slot] : slots_) changes_.push_back({light, recordValue(slot)});
}

void LocalShadows::bind(DescriptorWriter& writer) const {
  writer.storage(28, viewBuffer_.handle());
  atlas_.bind(writer, 29);
}

std::vector<uint32_t> LocalShadows::shadowed() const {
  std::vector<uint32_t> out;
  for (const auto& entry : slots_) out.push_back(entry.first);
  return out;
}

std::vector<std::pair<std::string, double>> LocalShadows::stats() const {
  if (!casting()) return {{"light-shadows", 0.0}};
  return {{"light-shadows", double(slots_.size())},
          {"light-shadow-compute-raster", atlas_.computeRaster() ? 1.0 : 0.0},
          {"light-shadow-views", double(viewsDrawn_)},
          {"light-shadow-casters", double(atlas_.castersDrawn())},
          {"light-shadow-resolution", double(options_.resolution)},
          {"light-shadow_bytes", atlas_.bytes()}};
}

}  // namespace lll
