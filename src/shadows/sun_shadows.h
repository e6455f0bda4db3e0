#pragma once
// The sun's shadow: cascaded shadow maps fitted to the view, in one depth atlas, read by every
// technique through common/sun_shadow.glsl (unlistedLight, the particles' scattering).
//
// Of the scene's directional lights the brightest casts the shadow; the others light unshadowed.
// Each frame the view frustum (near plane to far plane) is split into `cascades` slices, a blend
// of logarithmic and uniform splits (3:1, the logarithmic ones from 1/100 of the far plane); each slice gets
// the sphere around it (its size depends only on the slice, not on where the camera looks, so it never
// changes while the camera turns) and an orthographic projection along the sun whose origin is snapped to
// whole texels, so that as the camera moves the shadow's texels stay put on static geometry: no shimmer. Each
// projection's depth range spans the whole scene along the sun, so casters outside the slice still cast into
// it.
//
// The casters (shadows/shadow_casters.h) are drawn in one raster pass, "shadow-sun", a viewport per
// cascade. On the H200 culling single-sided materials' back faces took the pass from 4.7 to 3.6 ms,
// the other order of faces to 2.8 ms, at 4 cascades of 2048 on the sunlit atrium; the front-to-back
// order gained 1%.
// Lookups offset the point along its normal by a texel-sized step and bias the depth by the
// surface's slope to the sun (tan theta times a texel), then filter with 3x3 bilinear comparisons
// (`--shadow-filter pcf`) or read one texel (`none`: edges exactly where geometry puts them).
// `--shadow-raster compute` draws the opaque casters with the compute rasterizer instead
// (shadows/shadow_raster.h); alpha-masked ones are drawn by the hardware either way.
#include <glm/glm.hpp>

#include <string>
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

struct SunShadowOptions {
  uint32_t cascades = 4;       // 1 to kMaxCascades; 0: the sun casts no shadow
  uint32_t resolution = 2048;  // texels along each cascade's side
  uint32_t filter = gpu::kShadowFilterPcf;
  RasterChoice raster = RasterChoice::Auto;
};

// The options `settings` ask for (--shadows, --cascades, --shadow-resolution, --shadow-filter),
// checked: InputError naming the option for a value out of range.
SunShadowOptions sunShadowOptions(const RenderSettings& settings);

// The directional light that casts the shadow: the brightest (illuminance times the colour's mean),
// the first of equals; -1 when the scene has none.
int shadowCastingSun(const std::vector<DirectionalLight>& suns);

// Fits `options.cascades` cascades to the camera of `frame` (its view, near and far planes and field
// of view) for a sun shining towards -`towardSun`, over a scene inside `scene`. Fills every field of
// SunShadow.
gpu::SunShadow fitSunCascades(const gpu::FrameUniforms& frame, const glm::vec3& towardSun,
                              const Bounds& scene, const SunShadowOptions& options);

class SunShadows final : public DescriptorSource {
 public:
  // Throws InputError when the atlas would exceed the device's largest image.
  SunShadows(Context& context, const GpuScene& scene, const SunShadowOptions& options);
  SunShadows(const SunShadows&) = delete;
  SunShadows& operator=(const SunShadows&) = delete;

  // Whether a sun casts a shadow this run (the scene has a directional light and shadows are on).
  bool casting() const { return sun_ >= 0 && options_.cascades > 0; }
  // Fits the cascades to this frame's camera (its first directional light is the one that casts:
  // shadowCastingSun's) and uploads them; before recording the frame.
  void update(const gpu::FrameUniforms& frame, const Bounds& sceneBounds);
  // The "shadow-sun" pass (an untimed clear of the unused atlas when no sun casts), leaving the
  // atlas readable by every shader stage for the rest of the frame.
  void record(FrameContext& frame);
  // Bindings 26 (the cascades) and 27 (the atlas) of a lit pass.
  void bind(DescriptorWriter& writer) const override;

  const gpu::SunShadow& cascades() const { return data_; }
  std::vector<std::pair<std::string, double>> stats() const;

 private:
  // The views the casters are drawn from: each cascade's projection and cell.
  std::vector<ShadowView> views() const;

  Context& context_;
  const GpuScene& scene_;
  SunShadowOptions options_;
  int sun_ = -1;
  gpu::SunShadow data_{};
  Buffer uniforms_;
  ShadowAtlas atlas_;
};

}  // namespace lll
