#include "shadows/sun_shadows.h"

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

// How far the splits lean from uniform towards logarithmic (the "practical" split scheme), and
// where the logarithmic ones start, as a share of the far plane: from the camera's near plane,
// which reverse depth puts at 1/10,000 of the far one, three of four cascades would cover the
// first few percent of the view.
constexpr float kLogarithmicShare = 0.75f;
constexpr float kLogarithmicStart = 0.01f;
// The constant lookup bias in world units per unit of the scene's depth range (the others are
// every shadow map's: shared/shadow_types.h).
constexpr float kConstantBiasShare = 1e-4f;

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
  if (s.cascades < 1 || s.cascades > gpu::kMaxCascades)
    throw InputError(fmt::format("--cascades {}: expected 1 to {}", s.cascades, gpu::kMaxCascades));
  if (s.shadowResolution < 16 || s.shadowResolution > 8192)
    throw InputError(fmt::format("--shadow-resolution {}: expected 16 to 8192 texels", s.shadowResolution));
  o.raster = s.shadowRaster;
  o.cascades = s.shadows == ShadowMode::None ? 0 : s.cascades;
  o.resolution = s.shadowResolution;
  o.filter = s.shadowFilter == ShadowFilter::Pcf ? gpu::kShadowFilterPcf : gpu::kShadowFilterNone;
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
  out.bias = glm::vec4(gpu::kShadowNormalOffsetTexels, gpu::kShadowSlopeBiasTexels,
                       kConstantBiasShare * (farthest - closest), farthest - closest);
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
  ShadowAtlasDesc atlas;
  atlas.image = "sun-shadow-atlas";
  atlas.pass = "shadow-sun";
  atlas.raster = options_.raster;
  atlas.request = "--shadow-raster compute";
  if (casting()) {
    const uint32_t columns = std::min(options_.cascades, gpu::kCascadeColumns);
    const uint32_t rows = (options_.cascades + gpu::kCascadeColumns - 1) / gpu::kCascadeColumns;
    atlas.width = columns * options_.resolution;
    atlas.height = rows * options_.resolution;
    atlas.maxViews = options_.cascades;
    const uint32_t largest = context.properties().limits.maxImageDimension2D;
    if (atlas.width > largest || atlas.height > largest)
      throw InputError(fmt::format(
          "--shadow-resolution {} with --cascades {}: the shadow atlas would be {}x{} texels; this device's "
          "largest image is {} on a side",
          options_.resolution, options_.cascades, atlas.width, atlas.height, largest));
  }
  atlas_ = ShadowAtlas(context, scene, atlas);
  uniforms_ = Buffer(context, sizeof(gpu::SunShadow), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload,
                     "sun-shadow");
  uniforms_.upload(&data_, sizeof(data_));
}

std::vector<ShadowView> SunShadows::views() const {
  std::vector<ShadowView> out;
  const uint32_t size = options_.resolution;
  for (uint32_t c = 0; c < data_.config.x; ++c)
    out.push_back(
        {data_.cascadeViewProj[c], c % gpu::kCascadeColumns * size, c / gpu::kCascadeColumns * size, size});
  return out;
}

void SunShadows::update(const gpu::FrameUniforms& frame, const Bounds& sceneBounds) {
  data_ = casting() && sceneBounds.valid()
              ? fitSunCascades(frame, glm::vec3(frame.sunDirection[0]), sceneBounds, options_)
              : gpu::SunShadow{};
  atlas_.setViews(views());
  uniforms_.upload(&data_, sizeof(data_));
}

void SunShadows::record(FrameContext& frame) {
  atlas_.record(frame);
}

void SunShadows::bind(DescriptorWriter& writer) const {
  writer.storage(26, uniforms_.handle());
  atlas_.bind(writer, 27);
}

std::vector<std::pair<std::string, double>> SunShadows::stats() const {
  if (!casting()) return {{"sun-shadow-cascades", 0.0}};
  return {{"sun-shadow-cascades", double(options_.cascades)},
          {"sun-shadow-compute-raster", atlas_.computeRaster() ? 1.0 : 0.0},
          {"sun-shadow-resolution", double(options_.resolution)},
          {"sun-shadow_bytes", atlas_.bytes()}};
}

}  // namespace lll
