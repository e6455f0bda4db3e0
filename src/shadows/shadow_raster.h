#pragma once
// Shadow casters rasterized in compute (--shadow-raster compute): the visibility buffer's
// rasterizer (render/compute_raster.h, common/raster_triangle.glsl) pointed at a shadow atlas's
// views: the sun's cascades, or the local lights' cones and cube faces. On the H200 the hardware
// pass is bound by its few raster units; compute runs on all. The passes, named after the atlas
// ("shadow-sun", "shadow-lights"):
//   "shadow-sun"          one invocation per opaque caster triangle (every instance) draws it into
//                         each view's cell (a local light's views only when the triangle is within
//                         the light's range): small boxes covered with 64-bit atomic max, large
//                         triangles listed;
//   "shadow-sun-bins"     each large triangle appended to the 32x32-texel bins it touches, by a
//                         workgroup (the visibility buffer's thread-per-triangle listing took 3.6 ms
//                         of 5.3 on the H200: a near cascade's triangle spans thousands of bins);
//   "shadow-sun-resolve"  one invocation per texel of the views' cells keeps the nearest depth of its
//                         key and its bin's large triangles, and resets the key (the keys start
//                         clear, and the triangle pass writes only within the cells: no clear pass
//                         over the atlas, which keeps room for views a frame may not draw);
//   "shadow-sun-copy"     the cells' depths copied into a D32 atlas, where alpha-masked casters need
//                         it; otherwise the resolve writes an R32F atlas itself (the copy into a
//                         depth image cost more than the drawing on the H200, bench/README.md);
//   "shadow-sun-masked"   alpha-masked casters drawn by the hardware over that depth (they need
//                         their texture), only where the scene has them.
// Single-sided primitives are culled by their back faces, as the hardware pass culls them.
#include <span>
#include <string>
#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/compute_raster.h"
#include "shadows/shadow_casters.h"
#include "shared/shadow_types.h"

namespace lll {

class Context;
class GpuScene;
struct FrameContext;

class ShadowRaster {
 public:
  // Why `context`'s device cannot rasterize an atlas of width x height texels this way; empty
  // when it can.
  static std::string problem(const Context& context, uint32_t width, uint32_t height);

  // For an atlas of width x height texels holding at most `maxViews` views; `name` names its passes.
  // `intoImage`: the atlas is an R32F storage image the resolve writes; otherwise a D32 image the
  // depths are copied into (where the hardware draws alpha-masked casters over them).
  ShadowRaster(Context& context, const GpuScene& scene, uint32_t width, uint32_t height, uint32_t maxViews,
               std::string name, bool intoImage);

  // This frame's views (at most maxViews); before recording the frame.
  void setViews(std::span<const ShadowView> views);
  // Rasterizes every opaque caster into the views' cells of `atlas` (writing or copying the depths).
  void record(FrameContext& frame, const Image& atlas) const;

 private:
  Context& context_;
  const GpuScene& scene_;
  uint32_t width_;
  uint32_t height_;
  uint32_t maxViews_;
  std::string name_;
  uint32_t records_ = 0;
  uint32_t singleSided_ = 0;
  uint32_t triangles_ = 0;
  std::vector<VkRect2D> cells_;  // this frame's views' cells, resolved and copied into the atlas
  uint32_t largestCell_ = 0;
  bool intoImage_ = false;
  PipelineLayout layout_;
  Pipeline trianglePipeline_;
  Pipeline binPipeline_;
  Pipeline resolvePipeline_;
  Buffer recordBuffer_;  // SurfaceRecord per (instance, opaque primitive), single-sided first
  Buffer starts_;        // each record's first triangle, and the total
  Buffer instances_;
  Buffer views_;  // a uvec4 header (views, atlas width, height), then the views
  RasterWorkspace work_;
};

}  // namespace lll
