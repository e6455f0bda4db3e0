#pragma once
// Local lights' shadows (--shadows all): the K most important spot and point lights of each frame
// cast shadow maps, in one depth atlas, read by every technique's light evaluation through
// common/local_shadow.glsl (common/brdf.glsl's shadowedAttenuation).
//
// Which lights: each frame every point and spot light is scored by how much of the screen its
// sphere of reach covers times its intensity (candela times the colour's mean); the K best cast.
// A light that cast last frame keeps casting unless another scores kKeepShadow times more, and
// keeps its cell of the atlas while it does, so a slowly moving camera does not make shadows pop
// on and off between lights of nearly equal score. Box lights and virtual point lights cast none
// (instant radiosity's VPLs are unshadowed, as in Infinity).
//
// Views: a spot light's cone is one perspective view (its outer cone plus a 2-texel margin); a
// point light, or a spot wider than 120 degrees, is a cube of six 90-degree views (plus the same
// margin). All views are `resolution` texels square, reverse depth from 1/200 of the light's range
// to its range. The light record's spotParams.w names its views (shared/gpu_types.h), written into
// the light array on the GPU each frame only for the lights whose shadow changed.
//
// The casters are drawn in one pass, "shadow-lights": by the hardware (shadows/shadow_casters.h),
// each view seeing only the instances inside its frustum, or by the compute rasterizer
// (shadows/shadow_raster.h, --shadow-raster compute; auto's choice on a GPU), each triangle into
// the views of the lights whose range it is within, the alpha-masked casters then by the hardware. Lookups
// bias as the sun's do (a texel of normal offset, 2 texels of slope bias per unit tan(theta), the texel's
// size growing with the distance from the light) and filter with --shadow-filter's 3x3 PCF or one texel.
#include <glm/glm.hpp>

#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "scene/scene.h"
#include "shadows/shadow_atlas.h"
#include "shared/gpu_types.h"
#include "shared/shadow_types.h"

namespace lll {

class Context;
class GpuScene;
struct FrameContext;
struct RenderSettings;

// A light that cast last frame keeps casting unless another scores this many times more.
inline constexpr float kKeepShadow = 1.5f;
// Lights that reach farther than this (metres) cast no shadow.
inline constexpr float kFarthestShadow = 1e15f;
// Spots wider than this (outer cone angle, radians: 60 degrees) cast through a cube, as points do.
inline constexpr float kWidestShadowCone = 1.0471976f;

struct LocalShadowOptions {
  uint32_t lights = 0;        // K, the most lights that cast each frame; 0: none
  uint32_t resolution = 512;  // texels along each view's side
  uint32_t filter = gpu::kShadowFilterPcf;
  RasterChoice raster = RasterChoice::Auto;  // as the sun's (--shadow-raster)
};

// The options `settings` ask for (--shadows all, --shadow-lights, --shadow-light-resolution,
// --shadow-filter), checked: InputError naming the option for a value out of range.
LocalShadowOptions localShadowOptions(const RenderSettings& settings);

// How much `light` matters on screen this frame: the share of the view its sphere of reach covers
// (1 with the camera inside it, 0 outside the frustum) times its intensity times its colour's mean.
// 0 for lights that cannot cast (boxes, VPLs).
float shadowImportance(const Light& light, const gpu::FrameUniforms& frame);

// The lights that cast this frame: at most `count` of positive importance, the most important first,
// those in `previous` favoured by kKeepShadow; ties go to the lower index.
std::vector<uint32_t> selectShadowLights(const std::vector<Light>& lights, const gpu::FrameUniforms& frame,
                                         uint32_t count, std::span<const uint32_t> previous);

// Whether `light` casts through a cube of six views (points, and spots wider than kWidestShadowCone).
bool castsThroughCube(const Light& light);

// One view of a light: world to its clip space, and the tangent of its half-angle (margin included).
struct LightView {
  glm::mat4 viewProj{1.0f};
  float tanHalf = 1.0f;
};
// The views of `light` (one, or six cube faces +x, -x, +y, -y, +z, -z) for `resolution`-texel cells.
std::vector<LightView> shadowViews(const Light& light, uint32_t resolution);

class LocalShadows final : public DescriptorSource {
 public:
  // Throws InputError when the atlas for K lights does not fit this device's largest image.
  LocalShadows(Context& context, const GpuScene& scene, const LocalShadowOptions& options);
  LocalShadows(const LocalShadows&) = delete;
  LocalShadows& operator=(const LocalShadows&) = delete;

  bool casting() const { return options_.lights > 0 && (spotSlots_ + cubeSlots_) > 0; }
  // Chooses this frame's lights, fits their views, culls their casters; before recording the frame.
  void update(const gpu::FrameUniforms& frame);
  // Writes the changed lights' shadow views into the light array, then the "shadow-lights" pass
  // (an untimed clear when none casts), leaving the atlas readable by every shader stage.
  void record(FrameContext& frame);
  // Bindings 28 (the views) and 29 (the atlas) of a pass that evaluates lights.
  void bind(DescriptorWriter& writer) const override;
  // The light array was written again (moved lights): the casting lights' views go back into it
  // with the next frame.
  void lightsRewritten();

  // The lights casting this frame, by light index, in no particular order.
  std::vector<uint32_t> shadowed() const;
  std::vector<std::pair<std::string, double>> stats() const;

 private:
  struct Slot {
    bool cube = false;
    uint32_t index = 0;  // in its pool
  };
  uint32_t firstView(const Slot& slot) const { return slot.cube ? spotSlots_ + 6 * slot.index : slot.index; }
  // The light record's spotParams.w for a light in `slot` (common/local_shadow.glsl).
  float recordValue(const Slot& slot) const {
    return slot.cube ? -float(firstView(slot) + 1) : float(firstView(slot) + 1);
  }

  Context& context_;
  const GpuScene& scene_;
  LocalShadowOptions options_;
  uint32_t spotSlots_ = 0;  // single views, first in the atlas
  uint32_t cubeSlots_ = 0;  // six views each, after them
  uint32_t columns_ = 1;
  std::unordered_map<uint32_t, Slot> slots_;  // the casting lights and their slots
  // Writes not yet recorded (light, spotParams.w), in order: update() adds, record() writes them.
  std::vector<std::pair<uint32_t, float>> changes_;
  std::vector<gpu::LocalShadowView> views_;
  Buffer viewBuffer_;
  ShadowAtlas atlas_;
  uint32_t viewsDrawn_ = 0;
};

}  // namespace lll
